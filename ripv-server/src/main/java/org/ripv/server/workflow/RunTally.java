package org.ripv.server.workflow;

import java.util.List;

/**
 * What a run has done so far, counted from its steps' results, for the receipt and for a
 * {@code notify}'s {@code {fetched}}, {@code {ingested}} and {@code {failed}}: a message that can
 * only say what happened.
 */
final class RunTally {
    private final List<String> fetched;
    private int ingested;
    private int failedSteps;

    /** @param fetched the run's fetched files (kept across a cut call), read when asked */
    RunTally(List<String> fetched) {
        this.fetched = fetched;
    }

    void ingested(int files) {
        ingested += files;
    }

    void stepFailed() {
        failedSteps++;
    }

    int failedSteps() {
        return failedSteps;
    }

    int ingested() {
        return ingested;
    }

    int fetched() {
        return fetched.size();
    }

    /** {@code text} with {@code {fetched}}, {@code {ingested}} and {@code {failed}} replaced by the counts. */
    String fill(String text) {
        return text.replace("{fetched}", Integer.toString(fetched()))
                .replace("{ingested}", Integer.toString(ingested))
                .replace("{failed}", Integer.toString(failedSteps));
    }

    /** The receipt's line: {@code fetched 3, ingested 0, 1 step(s) failed}. */
    String describe() {
        return "fetched " + fetched() + ", ingested " + ingested + ", " + failedSteps + " step(s) failed";
    }
}
