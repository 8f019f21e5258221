package org.ripv.server.session;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Phaser;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.BiFunction;
import java.util.function.Consumer;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Message;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.SessionState;
import org.ripv.messages.VehicleEvent;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.store.StateStore;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The live console's centre: takes what services publish (and the events only the server sees:
 * locks, a service lost mid-call), derives each MailBox's state, appends to the transcript,
 * fans out to the MailBox's watchers and hands events to the notifier. Called on RMI threads
 * and the Post Office's; it never blocks on a client, the disk or the network.
 *
 * <p>Longer than 400 lines for one reason: taking a line, deriving the state, appending it and
 * handing it to the watchers (on this thread or the fan-out threads) all happen under the one
 * {@code order} lock that keeps every watcher's lines in the order they were taken; the fan-out's
 * shards are assigned and drained under it too, so splitting them off would split that invariant
 * across classes.
 */
public final class ConsoleHub implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(ConsoleHub.class);
    /** How many MailBoxes one connection may watch at once. */
    public static final int MAX_WATCHES_PER_CLIENT = 1024;
    /** Recent entries a new watcher gets with its {@code ?watch} reply. */
    static final int REPLAY = 20;
    /** Distinct MailBoxes one service may publish for (a hostile service cannot grow the state without end). */
    public static final int MAX_MAILBOXES_PER_SERVICE = 1_000;
    private static final long DAY_MILLIS = 24L * 3600 * 1000;
    private final Map<String, Set<String>> mailboxesOf = new ConcurrentHashMap<>();
    /**
     * A MailBox's first this many watchers get each push on the thread that takes the entries;
     * those beyond are spread over {@link #fanOut} threads, one per core, so that a line reaches
     * 1,000 pages in a fraction of the time one thread's 1,000 socket writes take (issue 38).
     */
    static final int INLINE_WATCHERS = 64;

    /** An event with what a notification needs: the MailBox's state and its last lines. */
    public record Notice(ConsoleEntry event, SessionState state, List<ConsoleEntry> lastLines) {}

    /** Turns a message into a frame's body (the server's codec). */
    public interface Encoder {
        byte[] encode(Message m) throws IOException;
    }

    private final Encoder encoder;
    private final Transcript transcript;
    private final VehicleStates states;
    private final Map<String, CopyOnWriteArrayList<Watcher>> watchers = new ConcurrentHashMap<>();
    private final Map<String, Set<Watcher>> byClient = new ConcurrentHashMap<>();
    private final Object order = new Object();
    /**
     * Fan-out threads: shard {@code i} (1 and up) runs on {@code fanOut[i - 1]}, shard 0 on the
     * taking thread under {@link #order}. A watcher keeps its shard for life, and each shard's
     * pushes run in the order the lines were taken, so every page still gets its lines in order.
     */
    private final ExecutorService[] fanOut;
    /** The next shard for a watcher beyond a MailBox's {@link #INLINE_WATCHERS}; guarded by {@code order}. */
    private int nextShard;
    /** Set under {@link #order} by {@link #close}: no entry is taken after the states and transcript stop. */
    private boolean closing;
    /** The last console sequence number given; guarded by {@code order}. */
    private long lastSeq;
    private volatile Consumer<Notice> notices = n -> { };
    private volatile Consumer<List<ConsoleEntry>> taps = l -> { };

    /**
     * @param transcripts  the transcripts directory (DATA/transcripts; each MailBox's state.json)
     * @param store        where transcript entries are kept
     * @param keepDays     transcript entries older than this many days are deleted
     * @param encoder      encodes a push once for all the watchers that are up to date
     */
    public ConsoleHub(Path transcripts, StateStore store, int keepDays, Encoder encoder) throws IOException {
        this(transcripts, store, keepDays, 0, encoder);
    }

    /** As above, keeping at most {@code dayCap} bytes of one MailBox's transcript a day (0: no cap). */
    public ConsoleHub(Path transcripts, StateStore store, int keepDays, long dayCap, Encoder encoder)
            throws IOException {
        this.encoder = encoder;
        this.transcript = new Transcript(transcripts, store, keepDays, dayCap);
        this.states = new VehicleStates(store);
        this.fanOut = new ExecutorService[Math.max(0, Math.min(8, Runtime.getRuntime().availableProcessors()) - 1)];
        for (int i = 0; i < fanOut.length; i++) {
            String name = "ripv-console-fanout-" + (i + 1);
            fanOut[i] = Executors.newSingleThreadExecutor(r -> new FanOutThread(r, name));
        }
    }

    /**
     * Who else reads every entry taken, numbered, in order (set once at start): the surface-dialog
     * reader. Called outside the hub's lock; it must not block.
     */
    public void onTaken(Consumer<List<ConsoleEntry>> tap) {
        this.taps = tap;
    }

    /** Where events go for notification (set once at start). */
    public void onEvent(Consumer<Notice> listener) {
        this.notices = listener;
    }

    public Transcript transcript() {
        return transcript;
    }

    /**
     * Entries a service published, treated as hostile: only those for well-formed MailBoxes under
     * {@code servicePrefix} (the service's full name) are taken, at most
     * {@link #MAX_MAILBOXES_PER_SERVICE} distinct MailBoxes per service; text is cut to
     * {@link Entries#MAX_TEXT} characters; a time more than a day away from the server's clock is
     * replaced by the server's. Null entries are ignored.
     */
    public void publish(String servicePrefix, List<ConsoleEntry> entries) {
        List<ConsoleEntry> mine = new ArrayList<>(entries.size());
        long now = System.currentTimeMillis();
        for (ConsoleEntry e : entries) {
            if (e == null || !e.mailbox().startsWith(servicePrefix) || e.mailbox().length() <= servicePrefix.length()
                    || !known(servicePrefix, e.mailbox())) {
                continue;
            }
            String text = e.text().length() <= Entries.MAX_TEXT ? e.text()
                    : e.text().substring(0, Entries.MAX_TEXT) + " [cut: " + (e.text().length() - Entries.MAX_TEXT) + " more characters]";
            long time = Math.abs(e.time() - now) > DAY_MILLIS ? now : e.time();
            String user = e.user().length() <= 64 ? e.user() : e.user().substring(0, 64);
            if (text != e.text() || time != e.time() || user != e.user()) {
                e = new ConsoleEntry(time, e.mailbox(), e.kind(), user, text, e.event(), e.lat(), e.lon());
            }
            mine.add(e);
        }
        if (!take(mine)) {
            // the service keeps what a server did not take and offers it to the next one
            throw new IllegalStateException("the server is stopping: console entries not taken");
        }
    }

    private static boolean wellFormed(String mailbox) {
        try {
            MailboxAddress.parse(mailbox);
            return true;
        } catch (IllegalArgumentException e) {
            return false;
        }
    }

    /** True when the MailBox is well formed and one the service may still add (or has already). */
    private boolean known(String servicePrefix, String mailbox) {
        Set<String> seen = mailboxesOf.computeIfAbsent(servicePrefix, k -> ConcurrentHashMap.newKeySet());
        if (seen.contains(mailbox)) {
            return true;
        }
        if (!wellFormed(mailbox)) {
            return false;
        }
        if (seen.size() >= MAX_MAILBOXES_PER_SERVICE) {
            log.warn("{} published for more than {} MailBoxes; ignoring {}", servicePrefix, MAX_MAILBOXES_PER_SERVICE, mailbox);
            return false;
        }
        seen.add(mailbox);
        return true;
    }

    /** An event the server itself observed (locks, a service lost mid-call). */
    public void serverEvent(String mailbox, VehicleEvent event, String user, String detail) {
        take(List.of(new ConsoleEntry(System.currentTimeMillis(), mailbox, ConsoleEntry.Kind.EVENT, user, detail, event,
                null, null)));
    }

    /** An entry the server itself wrote (a workflow's progress, receipt summary or end). */
    public void serverEntry(ConsoleEntry entry) {
        take(List.of(entry));
    }

    /**
     * A service left (died, was removed, or registered again): its MailBoxes on call are lost.
     *
     * @return the LINK_LOST events it published, for the others who follow calls (the workflows)
     */
    public List<ConsoleEntry> serviceGone(String servicePrefix, String why) {
        synchronized (order) {
            return lose(states.onCall(servicePrefix), "the service " + why + " during the call");
        }
    }

    /**
     * An instance of a service that started at {@code started} (epoch ms) registered, with these
     * MailBoxes: those still on a call last heard from before then are lost — the service
     * restarted during the call, perhaps together with the server, so nobody saw the call end. A
     * standby that takes over from a service that kept running keeps its calls.
     *
     * @return the LINK_LOST events it published
     */
    public List<ConsoleEntry> serviceStarted(String servicePrefix, long started, List<String> mailboxes) {
        if (started <= 0) {
            return List.of();
        }
        List<String> mine = claimed(servicePrefix, mailboxes);
        synchronized (order) {
            List<ConsoleEntry> lost = lose(mine.stream().filter(m -> states.onCallBefore(m, started)).toList(),
                    "the service restarted during the call");
            mine.forEach(m -> states.runStarted(m, started)); // calls are counted per run of the service, as it counts them
            return lost;
        }
    }

    /**
     * The MailBoxes a service says it has, taken as its word only: its own (under its prefix),
     * well formed, no more than it may publish for.
     */
    public static List<String> claimed(String servicePrefix, List<String> mailboxes) {
        return mailboxes.stream().filter(m -> m != null && m.startsWith(servicePrefix) && wellFormed(m))
                .distinct().limit(MAX_MAILBOXES_PER_SERVICE).toList();
    }

    private List<ConsoleEntry> lose(List<String> mailboxes, String why) {
        List<ConsoleEntry> lost = new ArrayList<>();
        for (String mailbox : mailboxes) {
            lost.add(new ConsoleEntry(System.currentTimeMillis(), mailbox, ConsoleEntry.Kind.EVENT, "", why,
                    VehicleEvent.LINK_LOST, null, null));
        }
        take(lost);
        return lost;
    }

    /**
     * The next console sequence number: one more than the last, and never below the clock in
     * microseconds, so that numbers keep increasing across a restart of the server (a client's
     * state from before it still orders the entries after it). Called under {@code order}.
     */
    private long nextSeq() {
        lastSeq = Math.max(lastSeq + 1, System.currentTimeMillis() * 1000);
        return lastSeq;
    }

    /** Numbers, stores and pushes entries; false when the hub is closing and took none of them. */
    private boolean take(List<ConsoleEntry> entries) {
        if (entries.isEmpty()) {
            return true;
        }
        List<Notice> events = new ArrayList<>();
        List<ConsoleEntry> numbered = new ArrayList<>(entries.size());
        Phaser spread = new Phaser(1);
        synchronized (order) {
            if (closing) {
                return false;
            }
            Map<String, List<ConsoleEntry>> byMailbox = new LinkedHashMap<>();
            for (ConsoleEntry taken : entries) {
                ConsoleEntry e = taken.withSeq(nextSeq());
                numbered.add(e);
                states.apply(e);
                transcript.append(e);
                byMailbox.computeIfAbsent(e.mailbox(), k -> new ArrayList<>()).add(e);
                if (e.kind() == ConsoleEntry.Kind.EVENT) {
                    events.add(new Notice(e, states.state(e.mailbox()), states.recent(e.mailbox(), 20)));
                }
            }
            byMailbox.forEach((mailbox, list) -> {
                List<Watcher> ws = watchers.get(mailbox);
                if (ws != null && !ws.isEmpty()) {
                    Watcher.Shared shared = new Watcher.Shared(Watcher.message(mailbox, list, 0), encoder);
                    if (ws.size() <= INLINE_WATCHERS || fanOut.length == 0) {
                        for (Watcher w : ws) {
                            if (w.shard == 0) {
                                w.offer(list, shared);
                            } else {
                                spread(spread, w.shard, new Watcher[] {w}, list, shared);
                            }
                        }
                    } else {
                        Watcher[] all = ws.toArray(new Watcher[0]); // who watches now: a later watch got these lines in its replay
                        for (int shard = 1; shard <= fanOut.length; shard++) {
                            spread(spread, shard, all, list, shared);
                        }
                        for (Watcher w : all) {
                            if (w.shard == 0) {
                                w.offer(list, shared);
                            }
                        }
                    }
                }
            });
        }
        // Before the service is answered: a service publishing faster than the pages are written to
        // waits, as it did when one thread wrote them all. Never under the lock nor on a fan-out
        // thread: a write that fails closes its page, whose released locks are entries taken here.
        if (Thread.holdsLock(order) || Thread.currentThread() instanceof FanOutThread) {
            spread.arriveAndDeregister();
        } else {
            spread.arriveAndAwaitAdvance();
        }
        try {
            taps.accept(numbered);
        } catch (RuntimeException x) {
            log.warn("a reader of console entries failed: {}", x.toString());
        }
        for (Notice n : events) {
            try {
                notices.accept(n);
            } catch (RuntimeException x) {
                log.warn("notification of {} failed: {}", n.event().event(), x.toString());
            }
        }
        return true;
    }

    /** A thread that writes pushes for the hub (see {@link #fanOut}). */
    private static final class FanOutThread extends Thread {
        FanOutThread(Runnable r, String name) {
            super(r, name);
            setDaemon(true);
        }
    }

    /** Offers a push on shard {@code shard}'s thread to those of {@code ws} on that shard; under {@code order}, so in the order taken. */
    private void spread(Phaser spread, int shard, Watcher[] ws, List<ConsoleEntry> list, Watcher.Shared shared) {
        spread.register();
        try {
            fanOut[shard - 1].execute(() -> {
                try {
                    for (Watcher w : ws) {
                        if (w.shard == shard) {
                            w.offer(list, shared);
                        }
                    }
                } catch (RuntimeException x) {
                    log.warn("a console push failed: {}", x.toString());
                } finally {
                    spread.arriveAndDeregister();
                }
            });
        } catch (RejectedExecutionException closing) {
            spread.arriveAndDeregister(); // the hub is closing: the watchers are stopped
        }
    }

    /**
     * Starts a watch: sends {@code reply} (built from the recent entries and state) through the
     * outlet first, so the client sees the replay before any live entry. Returns null, or why not.
     */
    public String watch(String clientId, String user, String mailbox, Outlet outlet,
                        BiFunction<SessionState, List<ConsoleEntry>, OutgoingServerMessage> reply) {
        synchronized (order) {
            Set<Watcher> mine = byClient.computeIfAbsent(clientId, k -> ConcurrentHashMap.newKeySet());
            if (mine.stream().anyMatch(w -> w.mailbox.equals(mailbox))) {
                outlet.send(reply.apply(states.state(mailbox), List.of()));
                return null;
            }
            if (mine.size() >= MAX_WATCHES_PER_CLIENT) {
                return "a connection may watch at most " + MAX_WATCHES_PER_CLIENT + " MailBoxes";
            }
            List<Watcher> already = watchers.get(mailbox);
            int shard = already == null || already.size() < INLINE_WATCHERS || fanOut.length == 0 ? 0
                    : nextShard++ % (fanOut.length + 1);
            Watcher w = new Watcher(clientId, user, mailbox, outlet, shard);
            mine.add(w);
            watchers.computeIfAbsent(mailbox, k -> new CopyOnWriteArrayList<>()).add(w);
            // Still under the lock, so no push can come first; and if sending closes the
            // connection (too far behind), clientClosed finds the watcher and removes it.
            outlet.send(reply.apply(states.state(mailbox), states.recent(mailbox, REPLAY)));
            if (!outlet.isOpen()) {
                clientClosed(clientId); // it closed while we registered: whether or not its close saw this watch
            }
            return null;
        }
    }

    /** Ends a watch; false when there was none. */
    public boolean unwatch(String clientId, String mailbox) {
        synchronized (order) {
            Set<Watcher> mine = byClient.get(clientId);
            if (mine == null) {
                return false;
            }
            for (Watcher w : mine) {
                if (w.mailbox.equals(mailbox)) {
                    remove(w);
                    mine.remove(w);
                    if (mine.isEmpty()) {
                        byClient.remove(clientId);
                    }
                    return true;
                }
            }
            return false;
        }
    }

    /** A connection closed: its watches go, and with them everything held for it. */
    public void clientClosed(String clientId) {
        synchronized (order) {
            Set<Watcher> mine = byClient.remove(clientId);
            if (mine != null) {
                mine.forEach(this::remove);
            }
        }
    }

    private void remove(Watcher w) {
        w.stop();
        watchers.computeIfPresent(w.mailbox, (k, list) -> {
            list.remove(w);
            return list.isEmpty() ? null : list;
        });
    }

    /**
     * The rules changed: every watch is checked again, and one whose user may no longer read its
     * MailBox ends, with a last message to that client saying why (see {@link Watcher#end}).
     *
     * @param whyNotRead null when the user (first argument) may read the MailBox (second), else why not
     * @return how many watches ended
     */
    public int recheck(BiFunction<String, String, String> whyNotRead) {
        int ended = 0;
        synchronized (order) {
            for (Map.Entry<String, Set<Watcher>> e : byClient.entrySet()) {
                for (Watcher w : List.copyOf(e.getValue())) {
                    String why = whyNotRead.apply(w.user, w.mailbox);
                    if (why != null) {
                        remove(w);
                        e.getValue().remove(w);
                        w.end(why);
                        ended++;
                        log.info("client {} ({}) no longer watches {}: {}", w.clientId, w.user, w.mailbox, why);
                    }
                }
            }
            byClient.values().removeIf(Set::isEmpty);
        }
        return ended;
    }

    /** The MailBoxes a connection watches. */
    public List<String> watching(String clientId) {
        Set<Watcher> mine = byClient.get(clientId);
        return mine == null ? List.of() : mine.stream().map(w -> w.mailbox).sorted().toList();
    }

    /** Watchers of all MailBoxes (tests and the benchmark check that nothing is left behind). */
    public int watcherCount() {
        return watchers.values().stream().mapToInt(List::size).sum();
    }

    /** Entries held in all watchers' backlogs now. */
    public long backlogTotal() {
        return watchers.values().stream().flatMap(List::stream).mapToLong(Watcher::backlog).sum();
    }

    /** Entries skipped so far for the watchers here now, each too slow to take them (tests and the benchmark). */
    public long skippedTotal() {
        return watchers.values().stream().flatMap(List::stream).mapToLong(Watcher::totalSkipped).sum();
    }

    /** A MailBox's call state, or null when it has never published anything. */
    public SessionState state(String mailbox) {
        return states.state(mailbox);
    }

    /** Reads the transcript ({@code ?history}); runs on the caller's thread, so not on the Post Office's. */
    public Transcript.Page history(String mailbox, Instant since, int last) throws IOException {
        return transcript.history(mailbox, since, last);
    }

    /** Why transcript entries are not being kept now, or null. */
    public String transcriptTrouble() {
        return transcript.trouble();
    }

    /** Waits (briefly) until every entry taken so far is in the transcript and every state change saved. */
    public void sync() {
        transcript.sync();
        states.sync();
    }

    @Override
    public void close() {
        // First no more entries (one being taken finishes), then the writers: an entry taken between
        // the two closes had its state save dropped but its line stored, and after a restart the
        // vehicle's state was UNKNOWN while its transcript went on (ServerAwayTest beside a CPU hog).
        synchronized (order) {
            closing = true;
            byClient.values().forEach(s -> s.forEach(Watcher::stop));
            byClient.clear();
            watchers.clear();
        }
        for (ExecutorService e : fanOut) {
            e.shutdown();
        }
        states.close();
        transcript.close();
    }
}
