package org.ripv.server.workflow;

/** Why a step stopped without a reply of its own to judge. Thrown within a run, never out of it. */
abstract sealed class StepStop extends Exception permits StepStop.Cut, StepStop.Failed, StepStop.Preempted {
    private static final long serialVersionUID = 1L;

    StepStop(String message) {
        super(message, null, false, false);
    }

    /** The call ended, or the server is stopping: the step runs again on the next call. */
    static final class Cut extends StepStop {
        private static final long serialVersionUID = 1L;

        Cut(String why) {
            super(why);
        }
    }

    /** The step's request failed without a reply to judge (no reply in time, the server overloaded). */
    static final class Failed extends StepStop {
        private static final long serialVersionUID = 1L;
        final String output;

        Failed(String message, String output) {
            super(message);
            this.output = output;
        }
    }

    /** An operator took the lock just as the step went out: it waits at its boundary again. */
    static final class Preempted extends StepStop {
        private static final long serialVersionUID = 1L;

        Preempted(String message) {
            super(message);
        }
    }
}
