package org.ripv.server.workflow;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.function.UnaryOperator;
import org.ripv.server.store.EmbeddedStateStore;
import org.ripv.server.store.StateStore;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The per-MailBox queues of workflows, kept in the server's {@link StateStore} (embedded: one
 * owner-only properties file per MailBox in {@code DATA/workflows/queues/}, written whole through
 * a temporary file and an atomic move), so that they survive restarts of the server and of
 * services. Thread-safe; every change is stored before the method returns.
 */
public final class WorkflowQueues {
    private static final Logger log = LoggerFactory.getLogger(WorkflowQueues.class);

    /** The most workflows one MailBox's queue may hold. */
    public static final int MAX_PER_MAILBOX = 100;
    /** The most workflows one user may have queued, over all MailBoxes, and their size in characters. */
    public static final int MAX_PER_USER = 200;
    public static final long MAX_CHARS_PER_USER = 8L << 20;
    /** The most workflows all queues together may hold, and their size in characters. */
    public static final int MAX_TOTAL = 10_000;
    public static final long MAX_CHARS_TOTAL = 128L << 20;

    private final StateStore store;
    private final Map<String, Queue> queues = new LinkedHashMap<>();

    private static final class Queue {
        long nextId = 1;
        final List<QueuedWorkflow> entries = new ArrayList<>();
    }

    /** Opens the queues in {@code dir} (files of their own), reading what an earlier server left there. */
    public WorkflowQueues(Path dir) throws IOException {
        this(new EmbeddedStateStore(EmbeddedStateStore.Layout.in(dir).withQueues(dir), 1 << 20));
    }

    /** Opens the queues kept in {@code store}, reading what an earlier server left there. */
    public WorkflowQueues(StateStore store) throws IOException {
        this.store = store;
        for (StateStore.Stored f : store.loadQueues()) {
            try {
                load(f.text());
            } catch (IOException | RuntimeException e) {
                // One damaged queue must not cost the other vehicles theirs; it stays for a person to look at.
                log.error("could not read the workflow queue {}: {}; it is left as it is", f.where(), e.toString());
            }
        }
    }

    private void load(String text) throws IOException {
        Properties p = new Properties();
        p.load(new StringReader(text));
        String mailbox = p.getProperty("mailbox");
        if (mailbox == null) {
            throw new IOException("no mailbox= line");
        }
        Queue q = new Queue();
        q.nextId = Long.parseLong(p.getProperty("next-id", "1"));
        int n = Integer.parseInt(p.getProperty("count", "0"));
        for (int i = 0; i < n; i++) {
            String k = "entry." + i + ".";
            String file = p.getProperty(k + "file");
            String source = p.getProperty(k + "source");
            for (String need : new String[] {"id", "owner", "file", "added", "source", "state"}) {
                if (p.getProperty(k + need) == null) {
                    throw new IOException("entry " + i + " has no " + need + "=");
                }
            }
            Workflow w = WorkflowParser.parse(file, source, name -> true);
            QueuedWorkflow.State state = QueuedWorkflow.State.valueOf(p.getProperty(k + "state"));
            if (state == QueuedWorkflow.State.RUNNING || state == QueuedWorkflow.State.PAUSED) {
                state = QueuedWorkflow.State.CUT; // the server stopped during the run
            }
            String fetched = p.getProperty(k + "fetched", "");
            q.entries.add(new QueuedWorkflow(Long.parseLong(p.getProperty(k + "id")), p.getProperty(k + "owner"), file,
                    Long.parseLong(p.getProperty(k + "added")), source, state,
                    Math.min(Integer.parseInt(p.getProperty(k + "next-step", "0")), w.steps().size() - 1),
                    Integer.parseInt(p.getProperty(k + "runs", "0")), p.getProperty(k + "last-error", ""),
                    fetched.isEmpty() ? List.of() : List.of(fetched.split("/")), w));
        }
        queues.put(mailbox, q);
    }

    private void save(String mailbox) throws IOException {
        Queue q = queues.get(mailbox);
        Properties p = new Properties();
        p.setProperty("mailbox", mailbox);
        p.setProperty("next-id", Long.toString(q.nextId));
        p.setProperty("count", Integer.toString(q.entries.size()));
        for (int i = 0; i < q.entries.size(); i++) {
            QueuedWorkflow e = q.entries.get(i);
            String k = "entry." + i + ".";
            p.setProperty(k + "id", Long.toString(e.id()));
            p.setProperty(k + "owner", e.owner());
            p.setProperty(k + "file", e.file());
            p.setProperty(k + "added", Long.toString(e.added()));
            p.setProperty(k + "source", e.source());
            p.setProperty(k + "state", e.state().name());
            p.setProperty(k + "next-step", Integer.toString(e.nextStep()));
            p.setProperty(k + "runs", Integer.toString(e.runs()));
            p.setProperty(k + "last-error", e.lastError());
            // '/' never occurs in a stored file name (FileNames)
            p.setProperty(k + "fetched", String.join("/", e.fetched()));
        }
        StringWriter w = new StringWriter();
        p.store(w, "RIPV workflow queue of " + mailbox + " (docs/workflows.md); written by the server");
        store.saveQueue(mailbox, w.toString());
    }

    /** Adds a parsed workflow at the end of a MailBox's queue. */
    public synchronized QueuedWorkflow add(String mailbox, String owner, String source, Workflow workflow) throws IOException {
        Queue existing = queues.get(mailbox);
        if (existing != null && existing.entries.size() >= MAX_PER_MAILBOX) {
            throw new IllegalArgumentException(mailbox + " has " + existing.entries.size() + " workflows queued already, the most "
                    + "one MailBox may have; remove some first");
        }
        capped(owner, source.length());
        Queue q = queues.computeIfAbsent(mailbox, k -> new Queue());
        QueuedWorkflow e = new QueuedWorkflow(q.nextId, owner, workflow.name(), System.currentTimeMillis(), source,
                QueuedWorkflow.State.QUEUED, 0, 0, "", List.of(), workflow);
        q.nextId++;
        q.entries.add(e);
        try {
            save(mailbox);
        } catch (IOException ex) {
            q.entries.remove(e);
            q.nextId--;
            throw ex;
        }
        return e;
    }

    /** True when the MailBox has a queue (it has existed: someone queued for it when it did). */
    public synchronized boolean has(String mailbox) {
        return queues.containsKey(mailbox);
    }

    /** Refuses a workflow past the per-user or total caps on count and size (issue 23, item 7). */
    private void capped(String owner, long chars) {
        int mine = 0;
        int all = 0;
        long mineChars = 0;
        long allChars = 0;
        for (Queue q : queues.values()) {
            for (QueuedWorkflow e : q.entries) {
                all++;
                allChars += e.source().length();
                if (e.owner().equals(owner)) {
                    mine++;
                    mineChars += e.source().length();
                }
            }
        }
        if (mine + 1 > MAX_PER_USER || mineChars + chars > MAX_CHARS_PER_USER) {
            throw new IllegalArgumentException(owner + " has " + mine + " workflows (" + mineChars + " characters) queued already;"
                    + " one user may have at most " + MAX_PER_USER + " (" + MAX_CHARS_PER_USER + " characters): remove some first");
        }
        if (all + 1 > MAX_TOTAL || allChars + chars > MAX_CHARS_TOTAL) {
            throw new IllegalArgumentException("the server holds " + all + " queued workflows (" + allChars + " characters), the"
                    + " most it keeps (" + MAX_TOTAL + ", " + MAX_CHARS_TOTAL + " characters); ask the operators to clear old ones");
        }
    }

    /** A MailBox's queue, in order. */
    public synchronized List<QueuedWorkflow> list(String mailbox) {
        Queue q = queues.get(mailbox);
        return q == null ? List.of() : List.copyOf(q.entries);
    }

    public synchronized Optional<QueuedWorkflow> get(String mailbox, long id) {
        return list(mailbox).stream().filter(e -> e.id() == id).findFirst();
    }

    /** Removes one entry; empty when there was none with that id. */
    public synchronized Optional<QueuedWorkflow> remove(String mailbox, long id) throws IOException {
        Queue q = queues.get(mailbox);
        if (q == null) {
            return Optional.empty();
        }
        for (int i = 0; i < q.entries.size(); i++) {
            if (q.entries.get(i).id() == id) {
                QueuedWorkflow e = q.entries.remove(i);
                try {
                    save(mailbox);
                } catch (IOException ex) {
                    q.entries.add(i, e);
                    throw ex;
                }
                return Optional.of(e);
            }
        }
        return Optional.empty();
    }

    /**
     * Replaces an entry with what {@code change} makes of it and writes the queue; empty when the
     * entry has been removed meanwhile.
     */
    public synchronized Optional<QueuedWorkflow> update(String mailbox, long id, UnaryOperator<QueuedWorkflow> change)
            throws IOException {
        Queue q = queues.get(mailbox);
        if (q == null) {
            return Optional.empty();
        }
        for (int i = 0; i < q.entries.size(); i++) {
            QueuedWorkflow old = q.entries.get(i);
            if (old.id() == id) {
                QueuedWorkflow now = change.apply(old);
                q.entries.set(i, now);
                try {
                    save(mailbox);
                } catch (IOException ex) {
                    q.entries.set(i, old);
                    throw ex;
                }
                return Optional.of(now);
            }
        }
        return Optional.empty();
    }

    /** Every MailBox with a queue file, empty queues included. */
    public synchronized List<String> mailboxes() {
        return List.copyOf(queues.keySet());
    }
}
