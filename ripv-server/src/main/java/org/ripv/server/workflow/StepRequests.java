package org.ripv.server.workflow;

import java.time.Duration;
import java.util.Map;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.List;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.permit.PermitFile;

/**
 * A run's requests: each step's request goes into the server's request path as the workflow's
 * owner, from the run's client id, and the runner waits for its final reply (or a line, for
 * {@code wait-for}). One request at a time; a call that ends cuts the one under way.
 */
final class StepRequests {
    private final Workflows workflows;
    private final String mailbox;
    private final CallGate gate;
    private final Map<String, CompletableFuture<OutgoingServerMessage>> replies = new ConcurrentHashMap<>();
    private final AtomicLong nextMessage = new AtomicLong(1);
    private volatile CompletableFuture<?> current;
    /** The step request under way: "MESSAGE-ID CLIENT-ID" as ?cancel takes them, or null. */
    private volatile String currentRequest;

    StepRequests(Workflows workflows, String mailbox, CallGate gate) {
        this.workflows = workflows;
        this.mailbox = mailbox;
        this.gate = gate;
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

    /** The call ended: the wait under way ends with a cut. */
    void cut(String why) {
        CompletableFuture<?> c = current;
        if (c != null) {
            c.completeExceptionally(new StepStop.Cut(why));
        }
    }

    /** A reply for one of this run's requests; only final ones are kept. */
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

    private StepStop.Cut ended() {
        return new StepStop.Cut("the call ended (" + gate.ended() + ")");
    }

    /** Sends one request as the workflow's owner and waits for its final reply. */
    OutgoingServerMessage send(QueuedWorkflow e, String clientId, String target, String body, Duration timeout)
            throws StepStop {
        if (gate.ended() != null) {
            throw ended();
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
            if (gate.ended() != null) {
                throw ended();
            }
            if (target.equals(mailbox) && !workflows.host.lockForWorkflow(mailbox, e.owner(), clientId,
                    System.currentTimeMillis() + Math.max(LockTurn.LOCK_MILLIS, timeout.toMillis() + 60_000))) {
                throw new StepStop.Preempted("an operator took the lock"); // long steps keep the lock for their whole timeout
            }
            if (!workflows.host.submit(h)) {
                throw new StepStop.Failed("the server is overloaded and did not take '" + Header.abbreviate(body) + "'", "");
            }
            OutgoingServerMessage r = f.get(timeout.toMillis(), TimeUnit.MILLISECONDS);
            if (r.status() == Status.ERROR && r.footer().errorCode() == ErrorCode.MAILBOX_LOCKED) {
                throw new StepStop.Preempted(r.footer().replyText());
            }
            return r;
        } catch (TimeoutException t) {
            workflows.host.cancel(clientId, id, "workflow " + e.id() + " (timeout)");
            throw new StepStop.Failed("no reply to '" + Header.abbreviate(body) + "' within " + timeout.toSeconds()
                    + " s (timeout=); asked the service to cancel it", "");
        } catch (ExecutionException x) {
            if (x.getCause() instanceof StepStop.Cut c) {
                throw c;
            }
            throw new StepStop.Failed(String.valueOf(x.getCause()), "");
        } catch (InterruptedException | CancellationException x) {
            Thread.currentThread().interrupt();
            throw new StepStop.Cut("the server is stopping");
        } finally {
            replies.remove(clientId + "#" + id);
            current = null;
            currentRequest = null;
        }
    }

    /** {@code wait-for}: waits for the vehicle's line the waiter was set up for before the step began. */
    Outcome waitFor(Step step, Workflows.LineWaiter w) throws StepStop {
        current = w.seen();
        try {
            if (gate.ended() != null) {
                throw ended();
            }
            return Outcome.ok(w.seen().get(step.timeout().toMillis(), TimeUnit.MILLISECONDS), List.of());
        } catch (TimeoutException t) {
            throw new StepStop.Failed("the vehicle printed no line matching '" + step.text() + "' within "
                    + step.timeout().toSeconds() + " s", "");
        } catch (ExecutionException x) {
            if (x.getCause() instanceof StepStop.Cut c) {
                throw c;
            }
            throw new StepStop.Failed(String.valueOf(x.getCause()), "");
        } catch (InterruptedException x) {
            Thread.currentThread().interrupt();
            throw new StepStop.Cut("the server is stopping");
        } finally {
            current = null;
        }
    }
}
