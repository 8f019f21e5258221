package org.ripv.server.workflow;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.Optional;

/**
 * A workflow's wait at a step boundary: it goes on once it holds the MailBox's operator lock
 * (taking it when free), is still queued, and the call goes on. While an operator holds the lock
 * the workflow is paused, and says so once; it says when it resumes.
 */
final class LockTurn {
    /** How far ahead a workflow's lock reaches; extended at every step. */
    static final long LOCK_MILLIS = 15 * 60_000L;

    private final Workflows workflows;
    private final String mailbox;
    private final CallGate gate;

    LockTurn(Workflows workflows, String mailbox, CallGate gate) {
        this.workflows = workflows;
        this.mailbox = mailbox;
        this.gate = gate;
    }

    /** Returns null to go on, "REMOVED" when the workflow left the queue, or why the run stops. */
    String await(QueuedWorkflow e, String clientId, int step) {
        Boundary b = new Boundary(e, clientId, step);
        return gate.await(b::check, () -> b.until, Optional.of("the server is stopping")).orElse(null);
    }

    /** One boundary's state: whether it said "paused", and when to look again. */
    private final class Boundary {
        final QueuedWorkflow e;
        final String clientId;
        final int step;
        boolean paused;
        long until;

        Boundary(QueuedWorkflow e, String clientId, int step) {
            this.e = e;
            this.clientId = clientId;
            this.step = step;
        }

        /** Empty to go on, a reason to stop, or null to wait. */
        Optional<String> check() {
            if (gate.ended() != null || workflows.closed()) {
                return Optional.of("the call ended (" + (gate.ended() == null ? "server stopping" : gate.ended())
                        + ") before step " + (step + 1));
            }
            if (workflows.queues.get(mailbox, e.id()).isEmpty()) {
                return Optional.of("REMOVED");
            }
            if (workflows.host.lockForWorkflow(mailbox, e.owner(), clientId, System.currentTimeMillis() + LOCK_MILLIS)) {
                if (paused) {
                    workflows.announce(mailbox, e.owner(), "workflow " + e.id() + " '" + e.file() + "': resumed");
                }
                return Optional.empty();
            }
            WorkflowHost.Lock other = workflows.host.lock(mailbox);
            if (!paused) {
                paused = true;
                try {
                    workflows.queues.update(mailbox, e.id(), q -> q.with(QueuedWorkflow.State.PAUSED, step, ""));
                } catch (IOException x) {
                    throw new UncheckedIOException(x);
                }
                workflows.announce(mailbox, e.owner(), "workflow " + e.id() + " '" + e.file() + "': paused before step "
                        + (step + 1) + ": " + (other == null ? "the lock is taken"
                        : Workflows.isWorkflowClient(other.clientId()) ? "another workflow run holds the lock"
                        : other.user() + " holds the lock"));
            }
            until = other == null ? System.currentTimeMillis() + 1000 : other.untilMillis() + 1;
            return null;
        }
    }
}
