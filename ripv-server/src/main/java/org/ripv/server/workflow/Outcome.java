package org.ripv.server.workflow;

import java.util.List;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;

/** A step's outcome: its verdict, what it printed, why it failed, the files it fetched. */
record Outcome(boolean ok, boolean cut, boolean preempted, String output, String error, List<Receipt.FileRecord> files) {

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

    /** The verdict on a step's final reply: ERROR fails; then the step's {@code fail=}, then its {@code expect=}. */
    static Outcome judged(Step step, OutgoingServerMessage r) {
        String text = r.footer().replyText();
        if (r.status() == Status.ERROR) {
            return failed(text, r.footer().errorCode() + ": " + text);
        }
        if (step.fail() != null && step.fail().matcher(text).find()) {
            return failed(text, "the reply matched fail=" + step.fail().pattern());
        }
        if (step.expect() != null && !step.expect().matcher(text).find()) {
            return failed(text, "the reply did not match expect=" + step.expect().pattern());
        }
        return ok(text, List.of());
    }
}
