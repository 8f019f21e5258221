package org.ripv.server.workflow;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.DigestInputStream;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.files.FileNames;
import org.ripv.server.permit.PermitFile;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs one MailBox's queue during one call: each workflow in order, each step through the
 * server's request path, holding the MailBox's operator lock for the workflow's duration. Stops
 * when the queue is done, a step fails (the workflow stays at the head for the next call), or
 * the call ends (the cut step runs again on the next call).
 */
final class Runner implements Runnable {
    private static final Logger log = LoggerFactory.getLogger(Runner.class);
    /** How far ahead a workflow's lock reaches; extended at every step. */
    static final long LOCK_MILLIS = 15 * 60_000L;
    /** The vehicle command that lists its files for {@code ymodem:get} globs. */
    static final String LIST_COMMAND = "dir";
    /** A PicoDOS/Slocum {@code dir} line: name, size, then date and time. */
    private static final Pattern DIR_LINE = Pattern.compile("^\\s*([^\\s/\\\\]+)\\s+(\\d+)\\s+\\S+\\s+\\S+\\s*$");

    final String mailbox;
    private final Workflows workflows;
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition changed = lock.newCondition();
    private final Map<String, CompletableFuture<OutgoingServerMessage>> replies = new ConcurrentHashMap<>();
    private final AtomicLong nextMessage = new AtomicLong(1);
    private volatile VehicleEvent ended;
    private volatile boolean finished;
    private volatile CompletableFuture<?> current;
    /** The step request under way: "MESSAGE-ID CLIENT-ID" as ?cancel takes them, or null. */
    private volatile String currentRequest;

    /** Why a step stopped without a verdict. */
    private static final class Cut extends Exception {
        private static final long serialVersionUID = 1L;

        Cut(String why) {
            super(why, null, false, false);
        }
    }

    /** A step's outcome. */
    private record Outcome(boolean ok, boolean cut, boolean preempted, String output, String error,
                           List<Receipt.FileRecord> files) {
        static Outcome ok(String output, List<Receipt.FileRecord> files) {
            return new Outcome(true, false, false, output, "", files);
        }

        static Outcome failed(String output, String error) {
            return new Outcome(false, false, false, output, error, List.of());
        }

        static Outcome cut(String why) {
            return new Outcome(false, true, false, "", why, List.of());
        }

        static Outcome preempted(String why) {
            return new Outcome(false, false, true, "", why, List.of());
        }
    }

    Runner(Workflows workflows, String mailbox) {
        this.workflows = workflows;
        this.mailbox = mailbox;
    }

    boolean finished() {
        return finished;
    }

    /** The call this runner ran for has ended: it starts nothing more, though it may still be writing its state. */
    boolean callHasEnded() {
        return ended != null;
    }

    void callEnded(VehicleEvent why) {
        lock.lock();
        try {
            ended = why == null ? VehicleEvent.LINK_LOST : why;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
        CompletableFuture<?> c = current;
        if (c != null) {
            c.completeExceptionally(new Cut(why == null ? "the server is stopping" : "the call ended (" + why + ")"));
        }
    }

    /** The step request under way, as {@code ?cancel} takes it ("MESSAGE-ID CLIENT-ID"), or null. */
    String currentRequest() {
        return currentRequest;
    }

    /** Cancels the step request under way (its workflow was removed). */
    void cancelCurrent(String byUser) {
        String r = currentRequest;
        if (r != null) {
            String[] w = r.split(" ");
            workflows.host.cancel(w[1], Long.parseLong(w[0]), byUser);
        }
    }

    void wake() {
        lock.lock();
        try {
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    void reply(OutgoingServerMessage reply) {
        if (!reply.status().isFinal()) {
            return;
        }
        CompletableFuture<OutgoingServerMessage> f = replies.remove(reply.header().origin().clientId() + "#"
                + reply.header().messageId());
        if (f != null) {
            f.complete(reply);
        }
    }

    @Override
    public void run() {
        Set<Long> ran = new HashSet<>();
        try {
            while (ended == null && !workflows.closed()) {
                Optional<QueuedWorkflow> next = workflows.queues.list(mailbox).stream().filter(e -> !ran.contains(e.id()))
                        .findFirst();
                if (next.isEmpty()) {
                    break;
                }
                ran.add(next.get().id());
                String result = runOne(next.get());
                if (!result.equals("DONE") && !result.equals("REMOVED")) {
                    break; // a failed workflow holds the head of the queue; a cut call stops everything
                }
            }
        } catch (IOException | RuntimeException e) {
            log.error("the workflow runner of {} stopped: {}", mailbox, e.toString(), e);
        } finally {
            finished = true;
            workflows.finished(mailbox, this);
        }
    }

    /** Runs one workflow from its next step; returns DONE, FAILED, CUT or REMOVED. */
    private String runOne(QueuedWorkflow entry) throws IOException {
        String clientId = workflows.newClientId();
        workflows.bind(clientId, this);
        Optional<QueuedWorkflow> started = workflows.queues.update(mailbox, entry.id(), QueuedWorkflow::started);
        if (started.isEmpty()) {
            workflows.unbind(clientId);
            return "REMOVED";
        }
        QueuedWorkflow e = started.get();
        Workflow wf = e.workflow();
        int total = wf.steps().size();
        String name = "workflow " + e.id() + " '" + e.file() + "'";
        Receipt receipt = new Receipt(mailbox, e.id(), e.file(), e.owner(), e.runs(), e.nextStep());
        List<String> fetchedNow = new ArrayList<>(e.fetched());
        try {
            workflows.announce(mailbox, e.owner(), name + ": " + (e.nextStep() == 0 ? "starting" : "resuming at step "
                    + (e.nextStep() + 1) + "/" + total) + " (run " + e.runs() + ")");
            int i = e.nextStep();
            while (i < total) {
                Step step = wf.steps().get(i);
                String boundary = awaitTurn(e, clientId, i);
                if (boundary != null) {
                    return finish(receipt, e, i, boundary.equals("REMOVED") ? "REMOVED" : "CUT", boundary, fetchedNow);
                }
                // A wait-for listens from before the step is shown as running, so no line slips past it.
                Workflows.LineWaiter waiter = step.kind() == Step.Kind.WAIT_FOR
                        ? workflows.waitFor(mailbox, Pattern.compile(step.text())) : null;
                long t0;
                Outcome o;
                try {
                    int index = i;
                    workflows.queues.update(mailbox, e.id(), q -> q.with(QueuedWorkflow.State.RUNNING, index, ""));
                    workflows.announce(mailbox, e.owner(), name + ": step " + (i + 1) + "/" + total + " " + step.describe());
                    t0 = System.currentTimeMillis();
                    o = runStep(e, clientId, step, fetchedNow, waiter);
                } finally {
                    if (waiter != null) {
                        workflows.stopWaiting(waiter);
                    }
                }
                if (o.preempted()) {
                    continue; // an operator took the lock just as the step went out: wait at this boundary again
                }
                receipt.steps.add(new Receipt.StepRecord(i, total, step.line(), step.describe(), t0, System.currentTimeMillis(),
                        o.ok() ? "OK" : o.cut() ? "CUT" : step.continueOnError() ? "FAILED (continue-on-error)" : "FAILED",
                        Receipt.cut(o.output()), o.files(), o.error()));
                List<String> keep = List.copyOf(fetchedNow);
                workflows.queues.update(mailbox, e.id(), q -> q.withFetched(keep));
                write(receipt);
                if (o.cut()) {
                    return finish(receipt, e, i, "CUT", "step " + (i + 1) + "/" + total + " was cut: " + o.error(), fetchedNow);
                }
                if (!o.ok() && !step.continueOnError()) {
                    return finish(receipt, e, i, "FAILED", "step " + (i + 1) + "/" + total + " (line " + step.line() + ") "
                            + step.describe() + " failed: " + o.error(), fetchedNow);
                }
                i++;
            }
            return finish(receipt, e, total, "DONE", "", fetchedNow);
        } finally {
            workflows.host.unlockWorkflow(mailbox, clientId);
            workflows.unbind(clientId);
            workflows.lockReleased(mailbox);
        }
    }

    private String finish(Receipt receipt, QueuedWorkflow e, int step, String result, String error, List<String> fetchedNow)
            throws IOException {
        String name = "workflow " + e.id() + " '" + e.file() + "'";
        receipt.result = result;
        receipt.error = error;
        receipt.ended = System.currentTimeMillis();
        switch (result) {
            case "DONE" -> {
                if (e.workflow().mode() == Workflow.Mode.ONCE) {
                    workflows.queues.remove(mailbox, e.id());
                } else {
                    workflows.queues.update(mailbox, e.id(), q -> q.with(QueuedWorkflow.State.QUEUED, 0, "").withFetched(List.of()));
                }
            }
            case "FAILED" -> workflows.queues.update(mailbox, e.id(), q -> q.with(QueuedWorkflow.State.FAILED, step, error));
            case "CUT" -> workflows.queues.update(mailbox, e.id(), q -> q.with(QueuedWorkflow.State.CUT, step, error));
            default -> { }
        }
        write(receipt);
        String summary = name + ": " + result.toLowerCase(java.util.Locale.ROOT) + (error.isEmpty() ? "" : ": " + error);
        if (result.equals("DONE")) {
            workflows.event(mailbox, VehicleEvent.WORKFLOW_DONE, summary);
        } else if (result.equals("FAILED")) {
            workflows.event(mailbox, VehicleEvent.WORKFLOW_FAILED, summary);
        } else {
            workflows.announce(mailbox, e.owner(), summary);
        }
        return result;
    }

    private void write(Receipt r) {
        try {
            workflows.receipts.write(r);
        } catch (IOException ex) {
            log.error("could not write the receipt of workflow {} on {}: {}", r.queueId, mailbox, ex.toString());
        }
    }

    /**
     * Waits at a step boundary until the workflow may go on: it holds the lock (taking it when
     * free), is still queued, and the call goes on. Returns null to go on, or why not.
     */
    private String awaitTurn(QueuedWorkflow e, String clientId, int step) throws IOException {
        boolean paused = false;
        lock.lock();
        try {
            while (true) {
                if (ended != null || workflows.closed()) {
                    return "the call ended (" + (ended == null ? "server stopping" : ended) + ") before step " + (step + 1);
                }
                if (workflows.queues.get(mailbox, e.id()).isEmpty()) {
                    return "REMOVED";
                }
                if (workflows.host.lockForWorkflow(mailbox, e.owner(), clientId, System.currentTimeMillis() + LOCK_MILLIS)) {
                    if (paused) {
                        workflows.announce(mailbox, e.owner(), "workflow " + e.id() + " '" + e.file() + "': resumed");
                    }
                    return null;
                }
                WorkflowHost.Lock other = workflows.host.lock(mailbox);
                if (!paused) {
                    paused = true;
                    workflows.queues.update(mailbox, e.id(), q -> q.with(QueuedWorkflow.State.PAUSED, step, ""));
                    workflows.announce(mailbox, e.owner(), "workflow " + e.id() + " '" + e.file() + "': paused before step "
                            + (step + 1) + ": " + (other == null ? "the lock is taken"
                            : Workflows.isWorkflowClient(other.clientId()) ? "another workflow run holds the lock"
                            : other.user() + " holds the lock"));
                }
                long until = other == null ? System.currentTimeMillis() + 1000 : other.untilMillis() + 1;
                try {
                    changed.awaitUntil(new java.util.Date(until));
                } catch (InterruptedException ie) {
                    Thread.currentThread().interrupt();
                    return "the server is stopping";
                }
            }
        } finally {
            lock.unlock();
        }
    }

    private Outcome runStep(QueuedWorkflow e, String clientId, Step step, List<String> fetchedNow, Workflows.LineWaiter waiter) {
        try {
            return switch (step.kind()) {
                case SEND -> judged(step, request(e, clientId, mailbox, step.text(), step.timeout()), List.of());
                case PUT -> {
                    if (!workflows.uploadExists(step.names().get(0))) {
                        yield Outcome.failed("", "no file '" + step.names().get(0) + "' in the upload store any more");
                    }
                    yield judged(step, request(e, clientId, mailbox, "ymodem:put " + step.names().get(0), step.timeout()), List.of());
                }
                case GET -> get(e, clientId, step, fetchedNow);
                case WAIT_FOR -> waitFor(step, waiter);
                case INGEST -> {
                    if (fetchedNow.isEmpty()) {
                        yield Outcome.ok("nothing fetched in this run: nothing to ingest", List.of());
                    }
                    StringBuilder out = new StringBuilder();
                    for (String f : fetchedNow) {
                        Outcome o = judged(step, request(e, clientId, step.to(), "ingest " + f, step.timeout()), List.of());
                        out.append(f).append(": ").append(o.ok() ? o.output() : o.error()).append('\n');
                        if (!o.ok()) {
                            yield new Outcome(false, o.cut(), o.preempted(), out.toString(), o.error(), List.of());
                        }
                    }
                    yield Outcome.ok(out.toString(), List.of());
                }
                case VIS -> judged(step, request(e, clientId, step.to(), step.text(), step.timeout()), List.of());
                case NOTIFY -> {
                    workflows.announce(mailbox, e.owner(), "workflow " + e.id() + " '" + e.file() + "': " + step.text());
                    yield Outcome.ok(step.text(), List.of());
                }
            };
        } catch (Cut c) {
            return Outcome.cut(c.getMessage());
        } catch (Preempted p) {
            return Outcome.preempted(p.getMessage());
        } catch (StepFailed f) {
            return Outcome.failed(f.output, f.getMessage());
        } catch (RuntimeException x) {
            // e.g. the owner was removed from the permit file, a MailBox address went bad
            return Outcome.failed("", x.getMessage() == null ? x.toString() : x.getMessage());
        }
    }

    /** A step's request failed without a reply to judge. */
    private static final class StepFailed extends Exception {
        private static final long serialVersionUID = 1L;
        final String output;

        StepFailed(String message, String output) {
            super(message, null, false, false);
            this.output = output;
        }
    }

    /** The lock went to an operator just as the step was sent. */
    private static final class Preempted extends Exception {
        private static final long serialVersionUID = 1L;

        Preempted(String message) {
            super(message, null, false, false);
        }
    }

    /** Sends one request as the workflow's owner and waits for its final reply. */
    private OutgoingServerMessage request(QueuedWorkflow e, String clientId, String target, String body,
                                          java.time.Duration timeout) throws Cut, Preempted, StepFailed {
        if (ended != null) {
            throw new Cut("the call ended (" + ended + ")");
        }
        PermitFile.User u = workflows.host.permits().user(e.owner()).orElseThrow(
                () -> new IllegalStateException("user '" + e.owner() + "' is no longer in the permit file"));
        long id = nextMessage.getAndIncrement();
        Header h = new Header(id, new IdBadge(clientId, e.owner()), u.roles(), "", target, body, Priority.NORMAL, null);
        CompletableFuture<OutgoingServerMessage> f = new CompletableFuture<>();
        replies.put(clientId + "#" + id, f);
        current = f;
        currentRequest = id + " " + clientId;
        try {
            if (ended != null) {
                throw new Cut("the call ended (" + ended + ")");
            }
            if (target.equals(mailbox) && !workflows.host.lockForWorkflow(mailbox, e.owner(), clientId,
                    System.currentTimeMillis() + Math.max(LOCK_MILLIS, timeout.toMillis() + 60_000))) {
                throw new Preempted("an operator took the lock"); // long steps keep the lock for their whole timeout
            }
            if (!workflows.host.submit(h)) {
                throw new StepFailed("the server is overloaded and did not take '" + Header.abbreviate(body) + "'", "");
            }
            OutgoingServerMessage r = f.get(timeout.toMillis(), TimeUnit.MILLISECONDS);
            if (r.status() == Status.ERROR && r.footer().errorCode() == ErrorCode.MAILBOX_LOCKED) {
                throw new Preempted(r.footer().replyText());
            }
            return r;
        } catch (TimeoutException t) {
            workflows.host.cancel(clientId, id, "workflow " + e.id() + " (timeout)");
            throw new StepFailed("no reply to '" + Header.abbreviate(body) + "' within " + timeout.toSeconds()
                    + " s (timeout=); asked the service to cancel it", "");
        } catch (ExecutionException x) {
            if (x.getCause() instanceof Cut c) {
                throw c;
            }
            throw new StepFailed(String.valueOf(x.getCause()), "");
        } catch (InterruptedException | CancellationException x) {
            Thread.currentThread().interrupt();
            throw new Cut("the server is stopping");
        } finally {
            replies.remove(clientId + "#" + id);
            current = null;
            currentRequest = null;
        }
    }

    /** OK replies are judged by the step's expect= and fail= regexes; ERROR replies fail. */
    private static Outcome judged(Step step, OutgoingServerMessage r, List<Receipt.FileRecord> files) {
        String text = r.footer().replyText();
        if (r.status() == Status.ERROR) {
            return Outcome.failed(text, r.footer().errorCode() + ": " + text);
        }
        if (step.fail() != null && step.fail().matcher(text).find()) {
            return Outcome.failed(text, "the reply matched fail=" + step.fail().pattern());
        }
        if (step.expect() != null && !step.expect().matcher(text).find()) {
            return Outcome.failed(text, "the reply did not match expect=" + step.expect().pattern());
        }
        return Outcome.ok(text, files);
    }

    private Outcome waitFor(Step step, Workflows.LineWaiter w) throws Cut, StepFailed {
        current = w.seen();
        try {
            if (ended != null) {
                throw new Cut("the call ended (" + ended + ")");
            }
            return Outcome.ok(w.seen().get(step.timeout().toMillis(), TimeUnit.MILLISECONDS), List.of());
        } catch (TimeoutException t) {
            throw new StepFailed("the vehicle printed no line matching '" + step.text() + "' within "
                    + step.timeout().toSeconds() + " s", "");
        } catch (ExecutionException x) {
            if (x.getCause() instanceof Cut c) {
                throw c;
            }
            throw new StepFailed(String.valueOf(x.getCause()), "");
        } catch (InterruptedException x) {
            Thread.currentThread().interrupt();
            throw new Cut("the server is stopping");
        } finally {
            current = null;
        }
    }

    /**
     * {@code ymodem:get}: lists the vehicle's files unless every name is literal and {@code all}
     * is given, picks the names and glob matches not fetched before with the same size, and
     * fetches them one file per request, so a cut call costs only the file it cut.
     */
    private Outcome get(QueuedWorkflow e, String clientId, Step step, List<String> fetchedNow)
            throws Cut, Preempted, StepFailed {
        boolean globs = step.names().stream().anyMatch(n -> n.indexOf('*') >= 0 || n.indexOf('?') >= 0);
        Map<String, Long> listing = new LinkedHashMap<>();
        if (globs || !step.all()) {
            OutgoingServerMessage dir = request(e, clientId, mailbox, LIST_COMMAND, step.timeout());
            if (dir.status() == Status.ERROR) {
                return Outcome.failed(dir.footer().replyText(), "listing the vehicle's files failed: "
                        + dir.footer().errorCode() + ": " + dir.footer().replyText());
            }
            listing.putAll(listing(dir.footer().replyText()));
        }
        List<String> wanted = new ArrayList<>();
        for (String n : step.names()) {
            if (n.indexOf('*') >= 0 || n.indexOf('?') >= 0) {
                Pattern g = glob(n);
                listing.keySet().stream().filter(k -> g.matcher(k).matches()).sorted().forEach(k -> {
                    if (!wanted.contains(k)) {
                        wanted.add(k);
                    }
                });
            } else if (!wanted.contains(n)) {
                wanted.add(n);
            }
        }
        StringBuilder out = new StringBuilder();
        List<Receipt.FileRecord> files = new ArrayList<>();
        int skipped = 0;
        for (String name : wanted) {
            Long size = listing.get(name);
            try {
                if (!step.all() && size != null && workflows.fetched.fetched(mailbox, name, size)) {
                    skipped++;
                    continue;
                }
            } catch (IOException x) {
                throw new StepFailed("could not read the list of fetched files: " + x.getMessage(), out.toString());
            }
            OutgoingServerMessage r = request(e, clientId, mailbox, "ymodem:get " + name, step.timeout());
            Outcome o = judged(step, r, List.of());
            out.append(r.footer().replyText().strip()).append('\n');
            if (!o.ok()) {
                return new Outcome(false, false, false, out.toString(), name + ": " + o.error(), files);
            }
            List<String> stored = new ArrayList<>();
            if (r.footer().result() instanceof FileListing l) {
                l.files().forEach(f -> stored.add(f.name()));
            }
            if (stored.isEmpty()) {
                stored.add(name);
            }
            for (String s : stored) {
                try {
                    Receipt.FileRecord rec = digest(s);
                    files.add(rec);
                    // remembered by the vehicle's name (the store may file it as HANDLE/NAME)
                    String plain = s.substring(s.lastIndexOf('/') + 1);
                    workflows.fetched.record(mailbox, plain, size != null && plain.equals(name) ? size : rec.size());
                    if (!fetchedNow.contains(s)) {
                        fetchedNow.add(s);
                    }
                } catch (IOException x) {
                    return new Outcome(false, false, false, out.toString(), "fetched " + s + " but could not read it from "
                            + "the download store: " + x.getMessage(), files);
                }
            }
        }
        if (wanted.isEmpty() || files.isEmpty()) {
            out.append(wanted.isEmpty() ? "no file on the vehicle matches " + String.join(" ", step.names())
                    : "nothing new: all " + skipped + " matching file(s) were fetched before with the same size");
        } else if (skipped > 0) {
            out.append(skipped).append(" file(s) skipped: fetched before with the same size");
        }
        return Outcome.ok(out.toString(), files);
    }

    /**
     * Size and SHA-256 of a file in the download store, read back from disk. {@code name} is as
     * the reply listed it: {@code NAME} or {@code HANDLE/NAME} (the MailBox's own folder).
     */
    private Receipt.FileRecord digest(String name) throws IOException {
        Path p = workflows.host.files().downloadDir();
        for (String part : name.split("/", -1)) {
            p = p.resolve(FileNames.check(part));
        }
        MessageDigest md;
        try {
            md = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException x) {
            throw new IllegalStateException(x);
        }
        long size = 0;
        try (InputStream in = new DigestInputStream(Files.newInputStream(p), md)) {
            byte[] buf = new byte[64 * 1024];
            for (int n; (n = in.read(buf)) > 0; ) {
                size += n;
            }
        }
        return new Receipt.FileRecord(name, size, HexFormat.of().formatHex(md.digest()));
    }

    /** The files of a {@code dir} listing, name to size; lines that are not a file are skipped. */
    static Map<String, Long> listing(String text) {
        Map<String, Long> out = new LinkedHashMap<>();
        for (String line : text.split("\r?\n")) {
            Matcher m = DIR_LINE.matcher(line);
            if (m.matches() && m.group(2).length() <= 18) {
                out.put(m.group(1), Long.parseLong(m.group(2)));
            }
        }
        return out;
    }

    /** {@code *} any run, {@code ?} one character, case-insensitive (PicoDOS names are). */
    static Pattern glob(String g) {
        StringBuilder b = new StringBuilder();
        for (char c : g.toCharArray()) {
            if (c == '*') {
                b.append(".*");
            } else if (c == '?') {
                b.append('.');
            } else {
                b.append(Pattern.quote(String.valueOf(c)));
            }
        }
        return Pattern.compile(b.toString(), Pattern.CASE_INSENSITIVE);
    }
}
