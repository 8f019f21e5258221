package org.ripv.server.workflow;

import java.io.IOException;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Pattern;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.files.FileNames;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.session.Rights;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

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
    private final Map<String, Runner> runners = new ConcurrentHashMap<>();
    private final Map<String, Runner> byClient = new ConcurrentHashMap<>();
    /** MailBoxes whose vehicle is on a call (SURFACED seen, no DIVED or LINK_LOST since). */
    private final java.util.Set<String> onCall = ConcurrentHashMap.newKeySet();
    private final List<LineWaiter> waiters = new CopyOnWriteArrayList<>();
    private final AtomicInteger nextClient = new AtomicInteger();
    private volatile boolean closed;

    /** Someone waiting for a vehicle line ({@code wait-for}). */
    record LineWaiter(String mailbox, Pattern regex, java.util.concurrent.CompletableFuture<String> seen) {}

    /**
     * @param store where queues, receipts and the fetched-file lists are kept (the server's state store)
     * @param host  the server
     */
    public Workflows(org.ripv.server.store.StateStore store, WorkflowHost host) throws IOException {
        this.host = host;
        this.queues = new WorkflowQueues(store);
        this.receipts = new Receipts(store);
        this.fetched = new FetchedFiles(store);
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
                    onCall.add(e.mailbox());
                    surfaced(e.mailbox());
                } else if (e.event() == VehicleEvent.DIVED || e.event() == VehicleEvent.LINK_LOST) {
                    onCall.remove(e.mailbox());
                    callEnded(e.mailbox(), e.event());
                }
            } else if (e.kind() == ConsoleEntry.Kind.LINE && !waiters.isEmpty()) {
                for (LineWaiter w : waiters) {
                    if (w.mailbox().equals(e.mailbox()) && w.regex().matcher(e.text()).find()) {
                        w.seen().complete(e.text());
                    }
                }
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
            if (queues.list(mailbox).isEmpty()) {
                return null;
            }
            Runner r = new Runner(this, mailbox);
            threads.execute(r);
            return r;
        });
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
        LineWaiter w = new LineWaiter(mailbox, regex, new java.util.concurrent.CompletableFuture<>());
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
        try {
            return queue(request);
        } catch (Refused e) {
            return request.reply(Footer.error(Ids.FID_QUEUE, ErrorCode.FORBIDDEN, e.getMessage()).via(SERVER));
        }
    }

    private OutgoingServerMessage queue(IncomingServerMessage request) throws IOException {
        String[] w = request.header().body().trim().split("\\s+");
        String user = request.header().origin().user();
        if (w.length == 2) {
            String mailbox = address(w[1]);
            mayRead(user, mailbox);
            return ok(request, Ids.FID_QUEUE, listing(mailbox));
        }
        String verb = w.length > 1 ? w[1].toLowerCase(Locale.ROOT) : "";
        switch (verb) {
            case "add" -> {
                usage(w.length == 4, "?queue add MAILBOX NAME");
                String mailbox = address(w[2]);
                mayRead(user, mailbox);
                PermitFile.User u = permitted(request);
                Workflow wf = read(w[3]);
                checkSteps(u, mailbox, wf);
                QueuedWorkflow e = queues.add(mailbox, user, sourceOf(w[3]), wf);
                if (onCall.contains(mailbox)) {
                    surfaced(mailbox); // the vehicle is on a call now: run it in this call
                }
                log.info("{} queued workflow {} '{}' ({} steps, {}) for {}", user, e.id(), e.file(), wf.steps().size(),
                        wf.mode().word(), mailbox);
                String when = onCall.contains(mailbox) ? "the vehicle is on a call: it runs now" : "it runs when the vehicle calls";
                return ok(request, Ids.FID_QUEUE, "queued workflow " + e.id() + " '" + e.file() + "' (" + wf.steps().size()
                        + " step(s), " + wf.mode().word() + ") for " + mailbox + "; " + when + "\n" + listing(mailbox));
            }
            case "remove" -> {
                usage(w.length == 4, "?queue remove MAILBOX ID");
                String mailbox = address(w[2]);
                mayRead(user, mailbox);
                long id;
                try {
                    id = Long.parseLong(w[3]);
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("ID must be a number from ?queue " + mailbox + ", got '" + w[3] + "'");
                }
                Optional<QueuedWorkflow> e = queues.get(mailbox, id);
                if (e.isEmpty()) {
                    return error(request, ErrorCode.BAD_REQUEST, "no workflow " + id + " in the queue of " + mailbox
                            + "; ?queue " + mailbox + " lists them");
                }
                mayChange(request, e.get());
                queues.remove(mailbox, id);
                Runner running = runners.get(mailbox);
                if (running != null && e.get().state() == QueuedWorkflow.State.RUNNING) {
                    running.cancelCurrent(user);
                }
                return ok(request, Ids.FID_QUEUE, "removed workflow " + id + " '" + e.get().file() + "' from " + mailbox
                        + (e.get().state() == QueuedWorkflow.State.RUNNING ? " (its run stops at the next step boundary)" : "")
                        + "\n" + listing(mailbox));
            }
            case "clear" -> {
                usage(w.length == 3, "?queue clear MAILBOX");
                String mailbox = address(w[2]);
                mayRead(user, mailbox);
                List<QueuedWorkflow> all = queues.list(mailbox);
                for (QueuedWorkflow e : all) {
                    mayChange(request, e);
                }
                for (QueuedWorkflow e : all) {
                    queues.remove(mailbox, e.id());
                }
                return ok(request, Ids.FID_QUEUE, "removed " + all.size() + " workflow(s) from " + mailbox);
            }
            default -> throw new IllegalArgumentException("usage: ?queue MAILBOX | ?queue add MAILBOX NAME | "
                    + "?queue remove MAILBOX ID | ?queue clear MAILBOX");
        }
    }

    /** {@code ?receipts MAILBOX [--last N]}. */
    public OutgoingServerMessage receiptsCommand(IncomingServerMessage request) throws IOException {
        try {
            return receipts(request);
        } catch (Refused e) {
            return request.reply(Footer.error(Ids.FID_RECEIPTS, ErrorCode.FORBIDDEN, e.getMessage()).via(SERVER));
        }
    }

    private OutgoingServerMessage receipts(IncomingServerMessage request) throws IOException {
        String[] w = request.header().body().trim().split("\\s+");
        int n = 5;
        if (w.length == 4 && w[2].equals("--last")) {
            try {
                n = Integer.parseInt(w[3]);
            } catch (NumberFormatException e) {
                n = -1;
            }
            if (n < 1 || n > 1000) {
                throw new IllegalArgumentException("--last takes 1 to 1000, got '" + w[3] + "'");
            }
        } else {
            usage(w.length == 2, "?receipts MAILBOX [--last N]");
        }
        String mailbox = address(w[1]);
        mayRead(request.header().origin().user(), mailbox);
        List<String> last = receipts.last(mailbox, n);
        if (last.isEmpty()) {
            return ok(request, Ids.FID_RECEIPTS, "no workflow receipts for " + mailbox + " yet");
        }
        return ok(request, Ids.FID_RECEIPTS, last.size() + " receipt(s) for " + mailbox + ", oldest first\n\n"
                + String.join("\n", last).stripTrailing());
    }

    private String listing(String mailbox) {
        List<QueuedWorkflow> list = queues.list(mailbox);
        if (list.isEmpty()) {
            return "the queue of " + mailbox + " is empty";
        }
        StringBuilder b = new StringBuilder(list.size() + " workflow(s) queued for " + mailbox + ", in the order they run:\n");
        b.append(String.format("%4s  %-10s %-12s %s%n", "ID", "OWNER", "MODE", "FILE, STATE"));
        Runner running = runners.get(mailbox);
        String request = running == null ? null : running.currentRequest();
        for (QueuedWorkflow e : list) {
            b.append(e.describe()).append(String.format("  (added %s)", Instant.ofEpochMilli(e.added())));
            if (e.state() == QueuedWorkflow.State.RUNNING && request != null) {
                b.append("  [step request: ?cancel ").append(request).append(']');
            }
            b.append('\n');
        }
        return b.toString().stripTrailing();
    }

    private static String address(String text) {
        try {
            return MailboxAddress.parse(text).toString();
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("'" + text + "' is not a MailBox address (" + e.getMessage() + "); ?mailboxes lists them");
        }
    }

    private static void usage(boolean ok, String usage) {
        if (!ok) {
            throw new IllegalArgumentException("usage: " + usage);
        }
    }

    /**
     * A queue and its receipts show what a vehicle is told and what it answered: reading them
     * needs the read right on the MailBox, as watching and {@code ?history} do ({@link Rights}).
     */
    private void mayRead(String user, String mailbox) {
        String why = Rights.whyNotRead(host.permits(), user, mailbox);
        if (why != null) {
            throw new Refused(why);
        }
    }

    /** The {@code ?queue …} command itself must be allowed (service RIPVServer, as for ?lock). */
    private PermitFile.User permitted(IncomingServerMessage request) {
        String user = request.header().origin().user();
        PermitFile p = host.permits();
        PermitFile.User u = p.user(user).orElseThrow(() -> new Refused("user '" + user + "' is no longer in the permit file"));
        PermitFile.Decision d = p.decide(u, SERVER, "", request.header().body().trim());
        if (!d.allowed()) {
            throw new Refused("user '" + user + "' may not change workflow queues (" + d.because() + ")");
        }
        return u;
    }

    /**
     * The owner removes their entry when the permit file allows them the command itself; anyone
     * else's needs a rule allowing {@code ?queue remove-any}.
     */
    private void mayChange(IncomingServerMessage request, QueuedWorkflow e) {
        String user = request.header().origin().user();
        if (e.owner().equals(user)) {
            permitted(request);
            return;
        }
        PermitFile p = host.permits();
        Optional<PermitFile.User> u = p.user(user);
        if (u.isEmpty() || !p.decide(u.get(), SERVER, "", "?queue remove-any").allowed()) {
            throw new Refused("workflow " + e.id() + " belongs to " + e.owner() + "; only they, or a user the permit file allows "
                    + "'?queue remove-any', may remove it");
        }
    }

    /** Every request the workflow will send must be one its owner may send (write rights on the MailBox). */
    private void checkSteps(PermitFile.User u, String mailbox, Workflow wf) {
        PermitFile p = host.permits();
        for (Step s : wf.steps()) {
            String target = s.to().isEmpty() ? mailbox : address(s.to());
            String command = switch (s.kind()) {
                case SEND, VIS -> s.text();
                case GET, PUT -> s.kind().word() + " " + String.join(" ", s.names());
                case INGEST -> "ingest";
                case WAIT_FOR, NOTIFY -> null;
            };
            if (command == null) {
                continue;
            }
            MailboxAddress a = MailboxAddress.parse(target);
            PermitFile.Decision d = p.decide(u, a.service().service(), a.handle(), command);
            if (!d.allowed()) {
                throw new Refused(wf.name() + ":" + s.line() + ": user '" + u.name() + "' may not send '" + command + "' to "
                        + target + " (" + d.because() + "), so the workflow could never run");
            }
            if (s.kind() == Step.Kind.GET && !s.all() && !p.decide(u, a.service().service(), a.handle(), "dir").allowed()) {
                throw new Refused(wf.name() + ":" + s.line() + ": ymodem:get lists the vehicle's files with 'dir', which user '"
                        + u.name() + "' may not send to " + target);
            }
        }
    }

    private String sourceOf(String name) throws IOException {
        byte[] bytes = host.files().readUpload(name);
        try {
            return StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(java.nio.ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            throw new WorkflowException(name, 0, "not UTF-8 text: a workflow file is text (docs/workflows.md)");
        }
    }

    /** Reads and parses an uploaded workflow file; refused whole with line and reason. */
    private Workflow read(String name) throws IOException {
        FileNames.check(name);
        if (!Files.isRegularFile(host.files().uploadDir().resolve(name))) {
            throw new NoSuchFileException("no file '" + name + "' in the upload store; upload the workflow first (put FILE)");
        }
        long size = Files.size(host.files().uploadDir().resolve(name));
        if (size > WorkflowParser.MAX_CHARS * 4L) {
            throw new WorkflowException(name, 0, "the file is " + size + " bytes; too large for a workflow");
        }
        return WorkflowParser.parse(name, sourceOf(name), this::uploadExists);
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
        threads.shutdown();
        try {
            if (!threads.awaitTermination(2, java.util.concurrent.TimeUnit.SECONDS)) {
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
