package org.ripv.server.workflow;

import java.time.Duration;
import java.util.List;
import java.util.Objects;
import com.google.re2j.Pattern;

/**
 * One line of a workflow file, parsed (docs/workflows.md).
 *
 * @param line            the line number in the file, for messages and receipts
 * @param kind            what the step does
 * @param text            the vehicle command ({@link Kind#SEND}), the regex ({@link Kind#WAIT_FOR}), the
 *                        command for the plotting service ({@link Kind#VIS}) or the message ({@link Kind#NOTIFY});
 *                        for {@link Kind#GET} and {@link Kind#PUT} the transfer's command word when it is
 *                        ZMODEM's ({@code zmodem:get}, {@code zmodem:put}), empty for YMODEM's
 * @param names           file names or globs ({@link Kind#GET}), the upload's name ({@link Kind#PUT})
 * @param expect          the reply must contain a match for success, or null
 * @param fail            a match in the reply fails the step, or null
 * @param timeout         how long the step may take
 * @param continueOnError a failure is written into the receipt and the workflow goes on
 * @param all             {@link Kind#GET}: fetch even files fetched before with the same name and size
 * @param to              the MailBox {@link Kind#INGEST} and {@link Kind#VIS} steps go to, or empty
 */
public record Step(int line, Kind kind, String text, List<String> names, Pattern expect, Pattern fail, Duration timeout,
                   boolean continueOnError, boolean all, String to) {

    /** What a step does. */
    public enum Kind {
        /** A command written to the vehicle. */
        SEND("send"),
        /** {@code ymodem:get} of names or globs. */
        GET("ymodem:get"),
        /** {@code ymodem:put} of an uploaded file. */
        PUT("ymodem:put"),
        /** Waits for a line of the vehicle's own output. */
        WAIT_FOR("wait-for"),
        /** Hands the files fetched in this run to the database's ingest. */
        INGEST("ingest"),
        /** A command for a DataVisServer MailBox. */
        VIS("vis"),
        /** A line for watchers, the transcript and the receipt. */
        NOTIFY("notify");

        private final String word;

        Kind(String word) {
            this.word = word;
        }

        /** The word that starts the step in a workflow file. */
        public String word() {
            return word;
        }
    }

    public Step {
        Objects.requireNonNull(kind, "kind");
        text = text == null ? "" : text;
        names = names == null ? List.of() : List.copyOf(names);
        to = to == null ? "" : to;
        Objects.requireNonNull(timeout, "timeout");
    }

    /** {@code ymodem:get}, {@code zmodem:get}, {@code ymodem:put} or {@code zmodem:put}: the command a GET or PUT sends. */
    public String transferWord() {
        return text.isEmpty() ? kind.word() : text;
    }

    /** The step as watchers and receipts show it, e.g. {@code ymodem:get *.DBD}. */
    public String describe() {
        return switch (kind) {
            case SEND -> text;
            case GET, PUT -> transferWord() + " " + String.join(" ", names) + (all ? " all" : "");
            case WAIT_FOR -> "wait-for " + text;
            case INGEST -> "ingest" + (to.isEmpty() ? "" : " to=" + to);
            case VIS -> "vis " + text + (to.isEmpty() ? "" : " to=" + to);
            case NOTIFY -> "notify " + text;
        };
    }
}
