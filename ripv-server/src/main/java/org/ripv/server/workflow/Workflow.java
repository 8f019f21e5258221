package org.ripv.server.workflow;

import java.util.List;
import java.util.Objects;

/**
 * A parsed workflow file: its name (the uploaded file's), whether it runs once or on every call,
 * and its steps in order.
 */
public record Workflow(String name, Mode mode, List<Step> steps) {

    /** How often a queued workflow runs. */
    public enum Mode {
        /** Runs on the next call and leaves the queue when it is done (the default). */
        ONCE("once"),
        /** Runs on every call and stays queued until removed. */
        EVERY_CALL("every-call");

        private final String word;

        Mode(String word) {
            this.word = word;
        }

        public String word() {
            return word;
        }
    }

    public Workflow {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(mode, "mode");
        steps = List.copyOf(steps);
    }
}
