package org.ripv.server.workflow;

import java.util.List;

/**
 * A workflow in a MailBox's queue, with its state between calls. Immutable; the queue replaces
 * an entry with a changed copy and writes the queue to disk.
 *
 * @param id        the entry's number in its MailBox's queue ({@code ?queue remove MAILBOX ID})
 * @param owner     the user who queued it; its steps run as this user, so the permit file applies
 * @param file      the uploaded workflow file's name
 * @param added     epoch milliseconds
 * @param source    the file's text as it was when queued (a later upload does not change it)
 * @param state     where it stands
 * @param nextStep  the index of the step to run next (0 = from the start)
 * @param runs      how many runs it has started
 * @param lastError why the last run stopped, or empty
 * @param fetched   files fetched by the run in progress (for {@code ingest}), kept across a cut call
 * @param workflow  the parsed file (not stored; parsed again from {@code source} on load)
 */
public record QueuedWorkflow(long id, String owner, String file, long added, String source, State state, int nextStep,
                             int runs, String lastError, List<String> fetched, Workflow workflow) {

    /** Where a queued workflow stands. */
    public enum State {
        /** Waiting for the next call. */
        QUEUED,
        /** Running now. */
        RUNNING,
        /** Running, but paused at a step boundary while an operator holds the lock. */
        PAUSED,
        /** A call ended in the middle: it resumes at {@code nextStep} on the next call. */
        CUT,
        /** A step failed: it stays at the head of the queue and retries that step on the next call. */
        FAILED
    }

    public QueuedWorkflow {
        lastError = lastError == null ? "" : lastError;
        fetched = fetched == null ? List.of() : List.copyOf(fetched);
    }

    QueuedWorkflow with(State newState, int newNext, String error) {
        return new QueuedWorkflow(id, owner, file, added, source, newState, newNext, runs, error, fetched, workflow);
    }

    /** A run begins: counted; it shows as running once its first step is under way. */
    QueuedWorkflow started() {
        return new QueuedWorkflow(id, owner, file, added, source, state, nextStep, runs + 1, lastError, fetched, workflow);
    }

    QueuedWorkflow withFetched(List<String> files) {
        return new QueuedWorkflow(id, owner, file, added, source, state, nextStep, runs, lastError, files, workflow);
    }

    /** A one-line summary for {@code ?queue}. */
    String describe() {
        int total = workflow.steps().size();
        String where = switch (state) {
            case QUEUED -> nextStep == 0 ? "queued" : "queued at step " + (nextStep + 1) + "/" + total;
            case RUNNING -> "running step " + (nextStep + 1) + "/" + total;
            case PAUSED -> "paused before step " + (nextStep + 1) + "/" + total + " (an operator holds the lock)";
            case CUT -> "cut at step " + (nextStep + 1) + "/" + total + ", resumes on the next call";
            case FAILED -> "failed at step " + (nextStep + 1) + "/" + total + ", retries it on the next call";
        };
        return String.format("%4d  %-10s %-12s %s  %d step(s), %s%s", id, owner, workflow.mode().word(), file, total, where,
                lastError.isEmpty() ? "" : ": " + lastError);
    }
}
