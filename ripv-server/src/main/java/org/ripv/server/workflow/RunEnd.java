package org.ripv.server.workflow;

import java.io.IOException;
import java.util.List;
import java.util.Locale;
import org.ripv.messages.VehicleEvent;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * How a run ends, in the queue, the receipt and the events: DONE (every step succeeded) and
 * DONE_WITH_ERRORS (it reached the end past {@code continue-on-error} failures) take a {@code once}
 * workflow off the queue (an {@code every-call} one starts again next call), FAILED and CUT keep
 * it at its step for the next call; WORKFLOW_DONE, WORKFLOW_DONE_WITH_ERRORS or WORKFLOW_FAILED
 * is published.
 */
final class RunEnd {
    private static final Logger log = LoggerFactory.getLogger(RunEnd.class);

    private final Workflows workflows;
    private final String mailbox;

    RunEnd(Workflows workflows, String mailbox) {
        this.workflows = workflows;
        this.mailbox = mailbox;
    }

    /** Ends the run with {@code result} (DONE, DONE_WITH_ERRORS, FAILED, CUT or REMOVED) at {@code step}; returns the result. */
    String finish(Receipt receipt, QueuedWorkflow e, int step, String result, String error) throws IOException {
        String name = "workflow " + e.id() + " '" + e.file() + "'";
        receipt.result = result;
        receipt.error = error;
        receipt.ended = System.currentTimeMillis();
        switch (result) {
            case "DONE", "DONE_WITH_ERRORS" -> {
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
        // The receipt also goes into the vehicle's transcript (without the outputs, which are there
        // already), so ?history tells the whole night's story.
        for (String line : receipt.render(false).split("\n")) {
            workflows.announce(mailbox, e.owner(), line);
        }
        String summary = name + ": " + result.toLowerCase(Locale.ROOT) + (error.isEmpty() ? "" : ": " + error);
        if (result.equals("DONE")) {
            workflows.event(mailbox, VehicleEvent.WORKFLOW_DONE, summary);
        } else if (result.equals("DONE_WITH_ERRORS")) {
            workflows.event(mailbox, VehicleEvent.WORKFLOW_DONE_WITH_ERRORS, summary);
        } else if (result.equals("FAILED")) {
            workflows.event(mailbox, VehicleEvent.WORKFLOW_FAILED, summary);
        } else {
            workflows.announce(mailbox, e.owner(), summary);
        }
        return result;
    }

    /** Writes the receipt as it stands (after every step, so a server that dies leaves it up to there). */
    void write(Receipt r) {
        try {
            workflows.receipts.write(r);
        } catch (IOException ex) {
            log.error("could not write the receipt of workflow {} on {}: {}", r.queueId, mailbox, ex.toString());
        }
    }
}
