package org.ripv.client.managers;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The workflow queues and receipts the client has looked at (docs/workflows.md), per vehicle
 * MailBox: what {@code ?queue MAILBOX} and {@code ?receipts MAILBOX} answered, read into rows,
 * and the outcome of the last change — with the line and reason when the server refused a
 * workflow file. Changed on the UI thread only; the workflow dialog listens and repaints.
 */
public final class WorkflowModel {

    /** One queued workflow, as {@code ?queue} lists it. */
    public record Entry(long id, String owner, String mode, String file, int steps, String state, String added) {}

    /** Why the server refused a workflow file: the line at fault (0: the file as a whole) and the reason. */
    public record Refusal(String file, int line, String reason) {
        @Override
        public String toString() {
            return (line > 0 ? "line " + line + ": " : "") + reason;
        }
    }

    /** One run's receipt: its first line, its result line and its whole text. */
    public record Receipt(String title, String result, String text) {
        private static final Pattern TITLE = Pattern.compile("^receipt: (workflow \\d+ '.*') of (\\S+) on .*, (run \\d+)$");

        /** The run's result word: RUNNING, DONE, DONE_WITH_ERRORS, FAILED, CUT or REMOVED. */
        public String verdict() {
            return result.isEmpty() ? "RUNNING" : result.replaceFirst("^result: (\\S+).*$", "$1");
        }

        /** True when the run did not do all it was asked: failed, cut, or done past failed steps. */
        public boolean hadErrors() {
            return switch (verdict()) {
                case "FAILED", "CUT", "DONE_WITH_ERRORS" -> true;
                default -> false;
            };
        }

        /** "DONE  workflow 1 'fetch.wf' (alice), run 2": the receipt list's words. */
        @Override
        public String toString() {
            String verdict = verdict();
            Matcher m = TITLE.matcher(title);
            return verdict + "  " + (m.matches() ? m.group(1) + " (" + m.group(2) + "), " + m.group(3) : title.replaceFirst("^receipt: ", ""));
        }
    }

    /** What the client knows of one MailBox's queue. */
    public record Queue(List<Entry> entries, String listing, List<Receipt> receipts, String outcome, boolean outcomeIsError,
                        List<Refusal> refusals, String nameTaken) {
        static final Queue EMPTY = new Queue(List.of(), "", List.of(), "", false, List.of(), "");
    }

    /** Told, on the UI thread, that a MailBox's queue view changed. */
    public interface Listener {
        void changed(String mailbox);
    }

    private final Map<String, Queue> queues = new HashMap<>();
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();

    public void addListener(Listener l) {
        listeners.add(l);
    }

    public void removeListener(Listener l) {
        listeners.remove(l);
    }

    /** The MailBox's queue as last seen (empty before the first {@code ?queue}). */
    public Queue queue(String mailbox) {
        return queues.getOrDefault(mailbox, Queue.EMPTY);
    }

    void listing(String mailbox, String text) {
        Queue q = queue(mailbox);
        put(mailbox, new Queue(parseListing(text), text, q.receipts(), q.outcome(), q.outcomeIsError(), q.refusals(), q.nameTaken()));
    }

    void receipts(String mailbox, String text) {
        Queue q = queue(mailbox);
        put(mailbox, new Queue(q.entries(), q.listing(), parseReceipts(text), q.outcome(), q.outcomeIsError(), q.refusals(),
                q.nameTaken()));
    }

    /** The outcome of a change (add, remove, clear); an error's text is read for the line at fault. */
    void outcome(String mailbox, String text, boolean error) {
        Queue q = queue(mailbox);
        put(mailbox, new Queue(q.entries(), q.listing(), q.receipts(), text, error, error ? parseRefusals(text) : List.of(), ""));
    }

    /** An upload for the queue was refused because the name is taken: the dialog asks keep or replace. */
    void nameTaken(String mailbox, String name, String text) {
        Queue q = queue(mailbox);
        put(mailbox, new Queue(q.entries(), q.listing(), q.receipts(), text, true, List.of(), name));
    }

    private void put(String mailbox, Queue q) {
        queues.put(mailbox, q);
        listeners.forEach(l -> l.changed(mailbox));
    }

    // ---- reading the server's words (docs/workflows.md "The queue", "Receipts")

    private static final Pattern ROW = Pattern.compile(
            "^\\s*(\\d+)\\s+(\\S+)\\s+(once|every-call)\\s+(.+?)\\s+(\\d+) step\\(s\\), (.*?)(?:\\s+\\(added ([^)]*)\\))?"
                    + "(?:\\s+\\[step request: [^]]*\\])?\\s*$");
    private static final Pattern REFUSAL = Pattern.compile("(?m)^(?:Error: )?(\\S+?):(\\d+): (.+)$");
    private static final Pattern WHOLE = Pattern.compile("(?m)^(?:Error: )?([^\\s:/]+\\.[A-Za-z0-9]+): (.+)$");

    /** The rows of a {@code ?queue} listing (its header and other lines are skipped). */
    static List<Entry> parseListing(String text) {
        List<Entry> out = new ArrayList<>();
        for (String line : text.split("\n")) {
            Matcher m = ROW.matcher(line);
            if (m.matches()) {
                out.add(new Entry(Long.parseLong(m.group(1)), m.group(2), m.group(3), m.group(4), Integer.parseInt(m.group(5)),
                        m.group(6), m.group(7) == null ? "" : m.group(7)));
            }
        }
        return List.copyOf(out);
    }

    /**
     * The line and reason of a refused workflow ({@code FILE:LINE: reason}, or {@code FILE: reason}
     * for the file as a whole); empty when the error names no file (rights, a missing upload).
     */
    static List<Refusal> parseRefusals(String text) {
        String t = text.replaceFirst("\\s*\\[[A-Z_]+(?: \\d+)?\\]\\s*$", "");
        Matcher m = REFUSAL.matcher(t);
        if (m.find()) {
            return List.of(new Refusal(m.group(1), Integer.parseInt(m.group(2)), m.group(3).strip()));
        }
        Matcher w = WHOLE.matcher(t);
        if (w.find()) {
            return List.of(new Refusal(w.group(1), 0, w.group(2).strip()));
        }
        return List.of();
    }

    /** The receipts in a {@code ?receipts} answer, newest first. */
    static List<Receipt> parseReceipts(String text) {
        List<Receipt> out = new ArrayList<>();
        StringBuilder cur = null;
        String title = "";
        String result = "";
        for (String line : text.split("\n", -1)) {
            if (line.startsWith("receipt: ")) {
                if (cur != null) {
                    out.add(0, new Receipt(title, result, cur.toString().strip()));
                }
                cur = new StringBuilder();
                title = line;
                result = "";
            }
            if (cur != null) {
                cur.append(line).append('\n');
                if (line.startsWith("result: ")) {
                    result = line;
                }
            }
        }
        if (cur != null) {
            out.add(0, new Receipt(title, result, cur.toString().strip()));
        }
        return List.copyOf(out);
    }
}
