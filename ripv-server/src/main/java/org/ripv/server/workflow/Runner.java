package org.ripv.server.workflow;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.VehicleEvent;
import org.ripv.patterns.UserPattern;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs one MailBox's queue during one call: each workflow in order, each step through the
 * server's request path, holding the MailBox's operator lock for the workflow's duration. Stops
 * when the queue is done or the call ends (the cut step runs again on the next call). A failed
 * step keeps its workflow at its place for the next call and holds back that owner's later
 * workflows; other users' workflows behind it still run.
 *
 * <p>Its parts: {@link CallGate} (the call, and waiting at a boundary), {@link LockTurn} (the
 * lock at each boundary, pause and resume), {@link StepRequests} (a step's request and its reply),
 * {@link FetchStep} ({@code ymodem:get}), {@link Outcome} (the verdict) and {@link RunEnd}.
 */
final class Runner implements Runnable {
    private static final Logger log = LoggerFactory.getLogger(Runner.class);

    final String mailbox;
    private final Workflows workflows;
    private final CallGate gate = new CallGate();
    private final LockTurn turns;
    private final StepRequests requests;
    private final FetchStep fetch;
    private final RunEnd end;
    private volatile boolean finished;

    Runner(Workflows workflows, String mailbox) {
        this.workflows = workflows;
        this.mailbox = mailbox;
        this.turns = new LockTurn(workflows, mailbox, gate);
        this.requests = new StepRequests(workflows, mailbox, gate);
        this.fetch = new FetchStep(workflows, mailbox, requests);
        this.end = new RunEnd(workflows, mailbox);
    }

    boolean finished() {
        return finished;
    }

    /** The call this runner ran for has ended: it starts nothing more, though it may still be writing its state. */
    boolean callHasEnded() {
        return gate.ended() != null;
    }

    void callEnded(VehicleEvent why) {
        gate.end(why);
        requests.cut(why == null ? "the server is stopping" : "the call ended (" + why + ")");
    }

    /** The step request under way, as {@code ?cancel} takes it ("MESSAGE-ID CLIENT-ID"), or null. */
    String currentRequest() {
        return requests.currentRequest();
    }

    /** Cancels the step request under way (its workflow was removed). */
    void cancelCurrent(String byUser) {
        requests.cancelCurrent(byUser);
    }

    void wake() {
        gate.wake();
    }

    void reply(OutgoingServerMessage reply) {
        requests.reply(reply);
    }

    @Override
    public void run() {
        Set<Long> ran = new HashSet<>();
        // A failed workflow holds back its owner's later workflows (their order is its owner's), never another user's:
        // one user's failing workflow must not block everyone's queue (issue 33 item 10).
        Set<String> held = new HashSet<>();
        try {
            sendToVehicle();
            while (gate.ended() == null && !workflows.closed()) {
                Optional<QueuedWorkflow> next = workflows.queues.list(mailbox).stream()
                        .filter(e -> !ran.contains(e.id()) && !held.contains(e.owner())).findFirst();
                if (next.isEmpty()) {
                    break;
                }
                ran.add(next.get().id());
                String result = runOne(next.get());
                if (result.equals("FAILED")) {
                    held.add(next.get().owner());
                } else if (!result.equals("DONE") && !result.equals("DONE_WITH_ERRORS") && !result.equals("REMOVED")) {
                    break; // a cut call stops everything
                }
            }
        } catch (IOException | RuntimeException e) {
            log.error("the workflow runner of {} stopped: {}", mailbox, e.toString(), e);
        } finally {
            finished = true;
            workflows.finished(mailbox, this);
        }
    }

    /** The MailBox's to-vehicle folder goes out first, from a client id of its own, under the lock like any step. */
    private void sendToVehicle() throws IOException {
        if (gate.ended() != null || workflows.closed()) {
            return;
        }
        String clientId = workflows.newClientId();
        workflows.bind(clientId, this);
        try {
            new ToVehicleRun(workflows, mailbox, requests).run(clientId);
        } finally {
            workflows.host.unlockWorkflow(mailbox, clientId);
            workflows.unbind(clientId);
            workflows.lockReleased(mailbox);
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
        RunTally tally = new RunTally(fetchedNow);
        receipt.tally = tally;
        try {
            workflows.announce(mailbox, e.owner(), name + ": " + (e.nextStep() == 0 ? "starting" : "resuming at step "
                    + (e.nextStep() + 1) + "/" + total) + " (run " + e.runs() + ")");
            int i = e.nextStep();
            while (i < total) {
                Step step = wf.steps().get(i);
                String boundary = turns.await(e, clientId, i);
                if (boundary != null) {
                    return end.finish(receipt, e, i, boundary.equals("REMOVED") ? "REMOVED" : "CUT", boundary);
                }
                // A wait-for listens from before the step is shown as running, so no line slips past it.
                Workflows.LineWaiter waiter = step.kind() == Step.Kind.WAIT_FOR
                        ? workflows.waitFor(mailbox, UserPattern.compile("wait-for", step.text()).pattern()) : null;
                long t0;
                Outcome o;
                try {
                    int index = i;
                    workflows.queues.update(mailbox, e.id(), q -> q.with(QueuedWorkflow.State.RUNNING, index, ""));
                    workflows.announce(mailbox, e.owner(), name + ": step " + (i + 1) + "/" + total + " " + step.describe());
                    t0 = System.currentTimeMillis();
                    o = runStep(e, clientId, step, fetchedNow, waiter, tally);
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
                if (!o.ok() && !o.cut()) {
                    tally.stepFailed();
                }
                List<String> keep = List.copyOf(fetchedNow);
                workflows.queues.update(mailbox, e.id(), q -> q.withFetched(keep));
                end.write(receipt);
                if (o.cut()) {
                    return end.finish(receipt, e, i, "CUT", "step " + (i + 1) + "/" + total + " was cut: " + o.error());
                }
                if (!o.ok() && !step.continueOnError()) {
                    return end.finish(receipt, e, i, "FAILED", "step " + (i + 1) + "/" + total + " (line " + step.line() + ") "
                            + step.describe() + " failed: " + o.error());
                }
                i++;
            }
            // continue-on-error lets a run go on past a failure, but not end as if nothing failed
            return tally.failedSteps() == 0 ? end.finish(receipt, e, total, "DONE", "")
                    : end.finish(receipt, e, total, "DONE_WITH_ERRORS", tally.failedSteps() + " step(s) failed (continue-on-error)");
        } finally {
            workflows.host.unlockWorkflow(mailbox, clientId);
            workflows.unbind(clientId);
            workflows.lockReleased(mailbox);
        }
    }

    private Outcome runStep(QueuedWorkflow e, String clientId, Step step, List<String> fetchedNow, Workflows.LineWaiter waiter,
                            RunTally tally) {
        try {
            return switch (step.kind()) {
                case SEND -> Outcome.judged(step, requests.send(e, clientId, mailbox, step.text(), step.timeout()));
                case PUT -> {
                    if (!workflows.uploadExists(step.names().get(0))) {
                        yield Outcome.failed("", "no file '" + step.names().get(0) + "' in the upload store any more");
                    }
                    yield Outcome.judged(step, requests.send(e, clientId, mailbox, step.transferWord() + " " + step.names().get(0), step.timeout()));
                }
                case GET -> fetch.run(e, clientId, step, fetchedNow, tally);
                case WAIT_FOR -> requests.waitFor(step, waiter);
                case INGEST -> {
                    if (fetchedNow.isEmpty()) {
                        yield Outcome.ok("nothing fetched in this run: nothing to ingest", List.of());
                    }
                    StringBuilder out = new StringBuilder();
                    for (String f : fetchedNow) {
                        Outcome o = Outcome.judged(step, requests.send(e, clientId, step.to(), "ingest " + f, step.timeout()));
                        out.append(f).append(": ").append(o.ok() ? o.output() : o.error()).append('\n');
                        if (!o.ok()) {
                            yield new Outcome(false, o.cut(), o.preempted(), out.toString(), o.error(), List.of());
                        }
                        tally.ingested(1);
                    }
                    yield Outcome.ok(out.toString(), List.of());
                }
                case VIS -> Outcome.judged(step, requests.send(e, clientId, step.to(), step.text(), step.timeout()));
                case NOTIFY -> {
                    String text = tally.fill(step.text());
                    workflows.announce(mailbox, e.owner(), "workflow " + e.id() + " '" + e.file() + "': " + text);
                    yield Outcome.ok(text, List.of());
                }
            };
        } catch (StepStop stop) {
            if (stop instanceof StepStop.Failed f) {
                return Outcome.failed(f.output, f.getMessage());
            }
            return stop instanceof StepStop.Cut ? Outcome.cut(stop.getMessage()) : Outcome.preempted(stop.getMessage());
        } catch (RuntimeException x) {
            // e.g. the owner was removed from the permit file, a MailBox address went bad
            return Outcome.failed("", x.getMessage() == null ? x.toString() : x.getMessage());
        }
    }
}
