package org.ripv.server.workflow;

import java.io.IOException;
import java.nio.file.Files;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import com.google.re2j.Pattern;
import org.ripv.commands.OptionValues;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.files.FileNames;
import org.ripv.server.store.StateStore;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * The workflow facility as the server sees it: the {@code ?queue} and {@code ?receipts}
 * commands, the console events that start and cut runs, and the replies to the steps' requests.
 * One {@link Runner} per MailBox runs while the vehicle is on a call.
 *
 * <p>Steps are requests from a client id of their own ({@code 010000}-{@code 099999}, never given
 * to a socket), carrying the workflow owner's name and roles, so the server's permits and locks
 * treat them like that user's commands.
 */
public final class Workflows implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Workflows.class);
    /** The server's name on the replies of its commands. */
    static final String SERVER = "RIPVServer";

    final WorkflowHost host;
    final WorkflowQueues queues;
    final Receipts receipts;
    final FetchedFiles fetched;
    private final ExecutorService threads;
    /**
     * Matches vehicle lines against {@code wait-for} patterns, off the service's console call: that
     * RMI thread carries every MailBox of the service, and no user's pattern may hold it (issue 23,
     * item 3). One thread, a bounded queue; lines beyond it are not matched and the drop is logged.
     */
    private final ThreadPoolExecutor lineMatcher = new ThreadPoolExecutor(1, 1,
            0, TimeUnit.MILLISECONDS, new ArrayBlockingQueue<>(4_096), r -> {
                Thread t = new Thread(r, "ripv-wait-for");
                t.setDaemon(true);
                return t;
            }, (r, pool) -> log.warn("wait-for: {} line batches waiting to be matched; this one is dropped", pool.getQueue().size()));
    private final Map<String, Runner> runners = new ConcurrentHashMap<>();
    private final Map<String, Runner> byClient = new ConcurrentHashMap<>();
    private final List<LineWaiter> waiters = new CopyOnWriteArrayList<>();
    private final AtomicInteger nextClient = new AtomicInteger();
    private final CallArrivals arrivals = new CallArrivals();
    private final WorkflowCommands commands;
    private volatile boolean closed;

    /** Someone waiting for a vehicle line ({@code wait-for}). */
    record LineWaiter(String mailbox, Pattern regex, CompletableFuture<String> seen) {}

    /**
     * @param store where queues, receipts and the fetched-file lists are kept (the server's state store)
     * @param host  the server
     */
    public Workflows(StateStore store, WorkflowHost host) throws IOException {
        this.host = host;
        this.queues = new WorkflowQueues(store);
        this.receipts = new Receipts(store);
        this.fetched = new FetchedFiles(store);
        this.commands = new WorkflowCommands(this);
        AtomicInteger n = new AtomicInteger();
        this.threads = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r, "ripv-workflow-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
    }

    /** True for the client ids workflow steps are sent from. */
    public static boolean isWorkflowClient(String clientId) {
        return clientId != null && clientId.length() == 6 && clientId.startsWith("0") && !clientId.startsWith("00");
    }

    String newClientId() {
        while (true) {
            String id = Integer.toString(10_000 + Math.floorMod(nextClient.getAndIncrement(), 90_000));
            String padded = "0" + id;
            if (!byClient.containsKey(padded)) {
                return padded;
            }
        }
    }

    void bind(String clientId, Runner r) {
        byClient.put(clientId, r);
    }

    void unbind(String clientId) {
        byClient.remove(clientId);
    }

    // ---- hooks the server calls ----

    /**
     * Console entries a service published: SURFACED starts the MailBox's queued workflows, DIVED
     * and LINK_LOST cut the run in progress, lines feed {@code wait-for}. Entries not for one of
     * the calling service's MailBoxes ({@code servicePrefix}) are ignored.
     */
    public void onConsole(String servicePrefix, List<ConsoleEntry> entries) {
        for (ConsoleEntry e : entries) {
            if (e == null || !e.mailbox().startsWith(servicePrefix)) {
                continue;
            }
            if (e.kind() == ConsoleEntry.Kind.EVENT) {
                if (e.event() == VehicleEvent.SURFACED) {
                    arrivals.surfaced(e.mailbox());
                    surfaced(e.mailbox());
                } else if (e.event() == VehicleEvent.DIVED || e.event() == VehicleEvent.LINK_LOST) {
                    callEnded(e.mailbox(), e.event());
                    listArrivals(e.mailbox());
                }
            }
        }
        if (!waiters.isEmpty() && !lineMatcher.isShutdown()) {
            lineMatcher.execute(() -> matchLines(servicePrefix, entries));
        }
    }

    private void matchLines(String servicePrefix, List<ConsoleEntry> entries) {
        for (ConsoleEntry e : entries) {
            if (e == null || e.kind() != ConsoleEntry.Kind.LINE || !e.mailbox().startsWith(servicePrefix)) {
                continue;
            }
            for (LineWaiter w : waiters) {
                if (w.mailbox().equals(e.mailbox()) && !w.seen().isDone() && w.regex().matcher(e.text()).find()) {
                    w.seen().complete(e.text());
                }
            }
        }
    }

    /**
     * A service registered (again, or with a server started again or a standby that took over)
     * with these MailBoxes: the queues of those whose vehicle is still on a call run now — a run
     * the server stopped in the middle resumes at its cut step — rather than on the next call.
     */
    public void serviceOnline(List<String> mailboxes) {
        for (String m : mailboxes) {
            if (host.onCall(m)) {
                surfaced(m);
            }
        }
    }

    /** The vehicle behind a MailBox is on a call: run its queue unless a run is under way. */
    void surfaced(String mailbox) {
        if (closed) {
            return;
        }
        runners.compute(mailbox, (k, old) -> {
            if (old != null && !old.finished() && !old.callHasEnded()) {
                return old;
            }
            // A runner of the last call may still be winding up: the new one waits at its first
            // step boundary for the old one's lock to go, and resumes where it left off.
            if (queues.list(mailbox).isEmpty() && !toVehicleWaiting(mailbox)) {
                return null;
            }
            Runner r = new Runner(this, mailbox);
            threads.execute(r);
            return r;
        });
    }

    private boolean toVehicleWaiting(String mailbox) {
        try {
            return !host.files().toVehiclePending(mailbox).isEmpty();
        } catch (IOException e) {
            log.warn("{}: cannot read its to-vehicle folder: {}", mailbox, e.toString());
            return false;
        }
    }

    /** Off the service's console thread: the folder is read on a workflow thread. */
    private void listArrivals(String mailbox) {
        if (closed) {
            return;
        }
        try {
            threads.execute(() -> {
                try {
                    String said = arrivals.ended(mailbox, host.files());
                    if (said != null) {
                        announce(mailbox, SERVER, said);
                    }
                } catch (IOException | RuntimeException x) {
                    log.warn("{}: cannot list what the call brought: {}", mailbox, x.toString());
                }
            });
        } catch (RejectedExecutionException x) {
            // stopping
        }
    }

    /** The call ended: the step under way is cut and the run stops; what is left runs on the next call. */
    void callEnded(String mailbox, VehicleEvent why) {
        Runner r = runners.get(mailbox);
        if (r != null) {
            r.callEnded(why);
        }
    }

    void finished(String mailbox, Runner r) {
        runners.remove(mailbox, r);
    }

    /**
     * A reply to a request; true when it was one of a workflow's steps (and so not for a socket).
     */
    public boolean reply(OutgoingServerMessage reply) {
        String clientId = reply.header().origin().clientId();
        if (!isWorkflowClient(clientId)) {
            return false;
        }
        Runner r = byClient.get(clientId);
        if (r != null) {
            r.reply(reply);
        } else if (reply.status().isFinal()) {
            log.debug("dropped a late reply to workflow step #{}: {}", reply.header().messageId(), reply.footer());
        }
        return true;
    }

    /** A MailBox's operator lock was released (null: some lock, e.g. of a client that left): paused runs look again. */
    public void lockReleased(String mailbox) {
        for (Runner r : runners.values()) {
            if (mailbox == null || r.mailbox.equals(mailbox)) {
                r.wake();
            }
        }
    }

    LineWaiter waitFor(String mailbox, Pattern regex) {
        LineWaiter w = new LineWaiter(mailbox, regex, new CompletableFuture<>());
        waiters.add(w);
        return w;
    }

    void stopWaiting(LineWaiter w) {
        waiters.remove(w);
    }

    /** Publishes a progress line for watchers and logs it. */
    void announce(String mailbox, String user, String text) {
        log.info("{}: {}", mailbox, text);
        try {
            host.publish(ConsoleEntry.command(mailbox, user, text));
        } catch (RuntimeException e) {
            log.debug("could not publish '{}': {}", text, e.toString());
        }
    }

    void event(String mailbox, VehicleEvent event, String text) {
        log.info("{}: {} {}", mailbox, event, text);
        try {
            host.publish(ConsoleEntry.event(mailbox, event, text, null, null));
        } catch (RuntimeException e) {
            log.debug("could not publish {}: {}", event, e.toString());
        }
    }

    // ---- ?queue and ?receipts ----

    /** {@code ?queue MAILBOX}, {@code ?queue add MAILBOX NAME}, {@code ?queue remove MAILBOX ID}, {@code ?queue clear MAILBOX}. */
    public OutgoingServerMessage queueCommand(IncomingServerMessage request) throws IOException {
        return commands.queue(request);
    }

    /**
     * Queues a workflow the server wrote for {@code user} (a plan's {@code put}, docs/plans.md),
     * checked as {@code ?queue add} checks a file: parsed whole, every step one the user may send.
     * Runs in this call when the vehicle is on one. Returns the workflow's id.
     *
     * @throws Refused            the user may not read the MailBox or send a step
     * @throws WorkflowException  the text is not a workflow
     */
    public long queueGenerated(String mailbox, String user, String label, String source) throws IOException {
        return commands.queueGenerated(mailbox, user, label, source);
    }

    /** The words of {@code ?receipts}, read by picocli through the server's command table. */
    public static final class ReceiptOptions {
        @Parameters(index = "0", paramLabel = "MAILBOX")
        String mailbox;
        @Option(names = "--last", paramLabel = "N", converter = OptionValues.Last.class)
        int last = 5;
    }

    /** {@code ?receipts MAILBOX [--last N]}. */
    public OutgoingServerMessage receiptsCommand(IncomingServerMessage request, ReceiptOptions options)
            throws IOException {
        return commands.receipts(request, options);
    }

    /** True while the MailBox's vehicle is on a call (the live console's call state: {@link WorkflowHost#onCall}). */
    boolean onCall(String mailbox) {
        return host.onCall(mailbox);
    }

    /** True for a MailBox that exists or has existed ({@link WorkflowHost#knownMailbox}). */
    boolean knownMailbox(String mailbox) {
        return host.knownMailbox(mailbox);
    }

    /** The run in progress for a MailBox, or null. */
    Runner running(String mailbox) {
        return runners.get(mailbox);
    }

    boolean uploadExists(String name) {
        try {
            FileNames.check(name);
        } catch (IllegalArgumentException e) {
            return false;
        }
        return Files.isRegularFile(host.files().uploadDir().resolve(name));
    }

    static OutgoingServerMessage ok(IncomingServerMessage request, String fid, String text) {
        return request.reply(Footer.ok(fid, text, null).via(SERVER));
    }

    static OutgoingServerMessage error(IncomingServerMessage request, ErrorCode code, String text) {
        return request.reply(Footer.error(Ids.FID_QUEUE, code, text).via(SERVER));
    }

    /** A refused command: the server answers it FORBIDDEN. */
    public static final class Refused extends SecurityException {
        private static final long serialVersionUID = 1L;

        Refused(String message) {
            super(message);
        }
    }

    boolean closed() {
        return closed;
    }

    /** Stops every run; their state is on disk and they resume on the next call after a restart. */
    @Override
    public void close() {
        closed = true;
        runners.values().forEach(r -> r.callEnded(null));
        // Let the runners write their state (they stop at once once the call is cut); an
        // interrupt could cut a queue write short.
        lineMatcher.shutdownNow();
        threads.shutdown();
        try {
            if (!threads.awaitTermination(2, TimeUnit.SECONDS)) {
                threads.shutdownNow();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            threads.shutdownNow();
        }
    }

    static boolean isFinal(Status s) {
        return s.isFinal();
    }
}
