package org.ripv.server.workflow;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Predicate;
import com.google.re2j.Pattern;
import org.ripv.patterns.UserPattern;
import org.ripv.server.files.FileNames;

/**
 * Reads a workflow file (docs/workflows.md). The whole file is refused, with the line and the
 * reason, when any step is unknown, an option is bad, a regex does not compile or an upload a
 * {@code ymodem:put} names is missing; nothing of a refused file is queued.
 *
 * <p>Words are split on white space. A word may be quoted, wholly or in part, as in a shell:
 * {@code '...'} keeps everything literally (the easy way to write a regex with backslashes), and
 * {@code "..."} keeps everything but {@code \"}, which stands for a quote. So
 * {@code expect="Glider .* at surface"} is one option whose value has spaces. An unquoted
 * {@code #} that starts a word begins a comment.
 */
public final class WorkflowParser {
    /** The most steps one file may have. */
    public static final int MAX_STEPS = 10_000;
    /** The longest file accepted, in characters. */
    public static final int MAX_CHARS = 1 << 20;
    /** The longest line accepted. */
    public static final int MAX_LINE = 4096;
    /** The longest step timeout. */
    public static final Duration MAX_TIMEOUT = Duration.ofHours(2);

    static final Duration SEND_TIMEOUT = Duration.ofSeconds(120);
    static final Duration TRANSFER_TIMEOUT = Duration.ofSeconds(900);
    static final Duration WAIT_TIMEOUT = Duration.ofSeconds(60);

    private WorkflowParser() {}

    /**
     * Parses a workflow file.
     *
     * @param name         the file's name, used in messages and as the workflow's name
     * @param text         the file's content
     * @param uploadExists whether a name is a file in the server's upload store ({@code ymodem:put})
     * @throws WorkflowException naming the line and the reason when the file cannot run
     */
    public static Workflow parse(String name, String text, Predicate<String> uploadExists) {
        if (text.length() > MAX_CHARS) {
            throw new WorkflowException(name, 0, "the file is " + text.length() + " characters; a workflow may have at most "
                    + MAX_CHARS);
        }
        Workflow.Mode mode = null;
        int modeLine = 0;
        List<Step> steps = new ArrayList<>();
        String[] lines = text.split("\r\n|\r|\n", -1);
        for (int i = 0; i < lines.length; i++) {
            int n = i + 1;
            String line = lines[i];
            if (line.length() > MAX_LINE) {
                throw new WorkflowException(name, n, "the line is " + line.length() + " characters; at most " + MAX_LINE);
            }
            if (line.indexOf('\0') >= 0) {
                throw new WorkflowException(name, n, "the line has a NUL character; a workflow is a text file");
            }
            List<String> words;
            try {
                words = words(line);
            } catch (IllegalArgumentException e) {
                throw new WorkflowException(name, n, e.getMessage());
            }
            if (words.isEmpty()) {
                continue;
            }
            String first = words.get(0).toLowerCase(Locale.ROOT);
            if (first.equals("workflow")) {
                if (mode != null) {
                    throw new WorkflowException(name, n, "a second 'workflow' line (the first is line " + modeLine + ")");
                }
                if (words.size() != 2) {
                    throw new WorkflowException(name, n, "write 'workflow once' or 'workflow every-call'");
                }
                mode = switch (words.get(1).toLowerCase(Locale.ROOT)) {
                    case "once" -> Workflow.Mode.ONCE;
                    case "every-call" -> Workflow.Mode.EVERY_CALL;
                    default -> throw new WorkflowException(name, n, "unknown mode '" + words.get(1)
                            + "': write 'workflow once' or 'workflow every-call'");
                };
                modeLine = n;
                continue;
            }
            if (steps.size() == MAX_STEPS) {
                throw new WorkflowException(name, n, "more than " + MAX_STEPS + " steps");
            }
            steps.add(step(name, n, words, uploadExists));
        }
        if (steps.isEmpty()) {
            throw new WorkflowException(name, 0, "no steps: a workflow needs at least one step (docs/workflows.md)");
        }
        return new Workflow(name, mode == null ? Workflow.Mode.ONCE : mode, steps);
    }

    private static Step step(String file, int n, List<String> words, Predicate<String> uploadExists) {
        String first = words.get(0).toLowerCase(Locale.ROOT);
        Step.Kind kind = null;
        for (Step.Kind k : Step.Kind.values()) {
            if (k.word().equals(first)) {
                kind = k;
            }
        }
        // ZMODEM's transfers are GET and PUT steps that send zmodem:get / zmodem:put (Step.transferWord)
        String zmodem = first.equals("zmodem:get") || first.equals("zmodem:put") ? first : "";
        if (!zmodem.isEmpty()) {
            kind = first.endsWith("get") ? Step.Kind.GET : Step.Kind.PUT;
        }
        if (kind == null) {
            throw new WorkflowException(file, n, "unknown step '" + words.get(0) + "': steps are send, ymodem:get, ymodem:put, "
                    + "zmodem:get, zmodem:put, "
                    + "wait-for, ingest, vis and notify (a vehicle command is written 'send COMMAND')");
        }
        // Positional words come first; options (key=value, flags) after them.
        List<String> args = new ArrayList<>();
        Pattern expect = null;
        Pattern fail = null;
        Duration timeout = null;
        boolean continueOnError = false;
        boolean all = false;
        String to = "";
        boolean inOptions = false;
        for (String w : words.subList(1, words.size())) {
            String lower = w.toLowerCase(Locale.ROOT);
            if (lower.startsWith("expect=")) {
                expect = regex(file, n, "expect", w.substring(7));
            } else if (lower.startsWith("fail=")) {
                fail = regex(file, n, "fail", w.substring(5));
            } else if (lower.startsWith("timeout=")) {
                timeout = duration(file, n, w.substring(8));
            } else if (lower.startsWith("to=")) {
                to = w.substring(3);
                if (to.isBlank() || !to.startsWith("<")) {
                    throw new WorkflowException(file, n, "to= needs a MailBox address such as <DatabaseServer>::<host>TTY1");
                }
            } else if (lower.equals("continue-on-error")) {
                continueOnError = true;
            } else if (lower.equals("all") && kind == Step.Kind.GET) {
                all = true;
            } else {
                if (inOptions) {
                    throw new WorkflowException(file, n, "'" + w + "' after the options: quote a command or regex that has "
                            + "spaces, and put the options (expect=, fail=, timeout=, to=, continue-on-error) last");
                }
                args.add(w);
                continue;
            }
            inOptions = true;
        }
        if (!to.isEmpty() && kind != Step.Kind.INGEST && kind != Step.Kind.VIS) {
            throw new WorkflowException(file, n, "to= belongs to ingest and vis steps; " + kind.word() + " goes to the workflow's MailBox");
        }
        if (timeout == null) {
            timeout = switch (kind) {
                case GET, PUT, INGEST -> TRANSFER_TIMEOUT;
                case WAIT_FOR -> WAIT_TIMEOUT;
                default -> SEND_TIMEOUT;
            };
        }
        String text = "";
        List<String> names = List.of();
        switch (kind) {
            case SEND, VIS, NOTIFY -> {
                if (args.isEmpty()) {
                    throw new WorkflowException(file, n, kind.word() + " needs " + (kind == Step.Kind.NOTIFY ? "a message"
                            : "a command") + ", e.g. " + (kind == Step.Kind.SEND ? "send dir" : kind == Step.Kind.VIS
                            ? "vis vis:track to=<DataVisServer>::<host>TTY1" : "notify \"logs fetched\""));
                }
                text = String.join(" ", args);
                if (kind == Step.Kind.SEND && (text.startsWith("?") || text.regionMatches(true, 0, "ymodem:", 0, 7)
                        || text.regionMatches(true, 0, "zmodem:", 0, 7))) {
                    throw new WorkflowException(file, n, "send writes a command to the vehicle; use the ymodem:get and "
                            + "ymodem:put steps (or zmodem:get and zmodem:put steps) for transfers, and the server's ? commands are not steps");
                }
                if (kind == Step.Kind.VIS && to.isEmpty()) {
                    throw new WorkflowException(file, n, "vis needs to=MAILBOX: the DataVisServer MailBox that plots");
                }
                if (kind == Step.Kind.NOTIFY && (expect != null || fail != null)) {
                    throw new WorkflowException(file, n, "notify has no reply to judge: expect= and fail= do not apply");
                }
            }
            case GET -> {
                if (args.isEmpty()) {
                    throw new WorkflowException(file, n, first + " needs file names or globs, e.g. " + first + " *.DBD");
                }
                for (String a : args) {
                    checkName(file, n, a.replace('*', 'x').replace('?', 'x'), a);
                }
                names = args;
                text = zmodem;
            }
            case PUT -> {
                if (args.size() != 1) {
                    throw new WorkflowException(file, n, first + " takes one uploaded file's name (one step per file)");
                }
                checkName(file, n, args.get(0), args.get(0));
                if (!uploadExists.test(args.get(0))) {
                    throw new WorkflowException(file, n, first + " " + args.get(0) + ": no such file in the upload store; "
                            + "upload it first (put FILE in the CLI)");
                }
                names = args;
                text = zmodem;
            }
            case WAIT_FOR -> {
                if (args.size() != 1) {
                    throw new WorkflowException(file, n, "wait-for takes one regex; quote it if it has spaces: "
                            + "wait-for \"Glider .* at surface\"");
                }
                text = args.get(0);
                regex(file, n, "wait-for", text);
            }
            case INGEST -> {
                if (!args.isEmpty()) {
                    throw new WorkflowException(file, n, "ingest takes no arguments: it ingests the files this run fetched");
                }
                if (to.isEmpty()) {
                    throw new WorkflowException(file, n, "ingest needs to=MAILBOX: the DatabaseServer MailBox that ingests");
                }
            }
        }
        return new Step(n, kind, text, names, expect, fail, timeout, continueOnError, all, to);
    }

    private static void checkName(String file, int n, String checked, String shown) {
        try {
            FileNames.check(checked);
        } catch (IllegalArgumentException e) {
            throw new WorkflowException(file, n, "'" + shown + "' is not a file name: " + e.getMessage());
        }
    }

    private static Pattern regex(String file, int n, String what, String re) {
        if (re.isEmpty()) {
            throw new WorkflowException(file, n, what + " needs a regex");
        }
        try {
            // RE2/J: linear time, so no user's pattern stalls a thread (issue 23, item 3).
            return UserPattern.compile("bad " + what + " regex", re).pattern();
        } catch (IllegalArgumentException e) {
            throw new WorkflowException(file, n, e.getMessage());
        }
    }

    /** {@code 30s}, {@code 5m}, {@code 1h}, {@code 500ms}, or plain seconds. */
    static Duration duration(String file, int n, String s) {
        String v = s.trim().toLowerCase(Locale.ROOT);
        long unit;
        String digits;
        if (v.endsWith("ms")) {
            unit = 1;
            digits = v.substring(0, v.length() - 2);
        } else if (v.endsWith("s")) {
            unit = 1000;
            digits = v.substring(0, v.length() - 1);
        } else if (v.endsWith("m")) {
            unit = 60_000;
            digits = v.substring(0, v.length() - 1);
        } else if (v.endsWith("h")) {
            unit = 3_600_000;
            digits = v.substring(0, v.length() - 1);
        } else {
            unit = 1000;
            digits = v;
        }
        long amount;
        try {
            amount = Long.parseLong(digits);
        } catch (NumberFormatException e) {
            throw new WorkflowException(file, n, "bad timeout '" + s + "': write e.g. 30s, 5m, 1h or 500ms");
        }
        if (amount <= 0 || amount > MAX_TIMEOUT.toMillis() / unit) {
            throw new WorkflowException(file, n, "timeout '" + s + "' is out of range: more than 0 and at most 2h");
        }
        return Duration.ofMillis(amount * unit);
    }

    /** Splits a line into words, honouring quotes; a word starting with an unquoted # ends the line. */
    static List<String> words(String line) {
        List<String> out = new ArrayList<>();
        StringBuilder w = new StringBuilder();
        boolean inWord = false;
        int i = 0;
        int len = line.length();
        while (i < len) {
            char c = line.charAt(i);
            if (Character.isWhitespace(c)) {
                if (inWord) {
                    out.add(w.toString());
                    w.setLength(0);
                    inWord = false;
                }
                i++;
            } else if (c == '#' && !inWord) {
                break;
            } else if (c == '\'') {
                int end = line.indexOf('\'', i + 1);
                if (end < 0) {
                    throw new IllegalArgumentException("a ' quote opened at column " + (i + 1) + " is not closed");
                }
                w.append(line, i + 1, end);
                inWord = true;
                i = end + 1;
            } else if (c == '"') {
                int j = i + 1;
                boolean closed = false;
                while (j < len) {
                    char d = line.charAt(j);
                    if (d == '\\' && j + 1 < len && line.charAt(j + 1) == '"') {
                        w.append('"');
                        j += 2;
                    } else if (d == '"') {
                        closed = true;
                        break;
                    } else {
                        w.append(d);
                        j++;
                    }
                }
                if (!closed) {
                    throw new IllegalArgumentException("a \" quote opened at column " + (i + 1) + " is not closed");
                }
                inWord = true;
                i = j + 1;
            } else {
                w.append(c);
                inWord = true;
                i++;
            }
        }
        if (inWord) {
            out.add(w.toString());
        }
        return out;
    }
}
