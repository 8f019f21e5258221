package org.ripv.server.workflow;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;

/**
 * What one run of a workflow did: each step with its times, its reply (cut), the files it moved
 * with size and SHA-256, and why it stopped. Built by the runner as the run goes; written after
 * every step, so a server that dies mid-run leaves the receipt up to there.
 */
final class Receipt {
    /** Longest reply text a receipt keeps per step. */
    static final int MAX_OUTPUT = 2000;

    /** One file a step moved. */
    record FileRecord(String name, long size, String sha256) {}

    /** One step's record. */
    record StepRecord(int index, int total, int line, String step, long started, long ended, String verdict, String output,
                      List<FileRecord> files, String error) {}

    final String mailbox;
    final long queueId;
    final String file;
    final String owner;
    final int run;
    final long started;
    final int firstStep;
    final List<StepRecord> steps = new ArrayList<>();
    long ended;
    String result = "RUNNING";
    /** What the run has done so far (null in receipts of runs that had none, e.g. before it started). */
    RunTally tally;
    String error = "";

    Receipt(String mailbox, long queueId, String file, String owner, int run, int firstStep) {
        this.mailbox = mailbox;
        this.queueId = queueId;
        this.file = file;
        this.owner = owner;
        this.run = run;
        this.firstStep = firstStep;
        this.started = System.currentTimeMillis();
    }

    static String cut(String s) {
        String t = s == null ? "" : s.strip();
        return t.length() <= MAX_OUTPUT ? t : t.substring(0, MAX_OUTPUT) + "... (" + t.length() + " characters, cut)";
    }

    /** The file name the receipt is stored under: sorts by time. */
    String fileName() {
        return String.format("%013d-%d-%d.txt", started, queueId, run);
    }

    String render() {
        return render(true);
    }

    /** The receipt as text; without {@code outputs} for the transcript, which has the vehicle's output already. */
    String render(boolean outputs) {
        StringBuilder b = new StringBuilder();
        b.append("receipt: workflow ").append(queueId).append(" '").append(file).append("' of ").append(owner)
                .append(" on ").append(mailbox).append(", run ").append(run).append('\n');
        b.append("started: ").append(Instant.ofEpochMilli(started))
                .append(firstStep > 0 ? "  (resumed at step " + (firstStep + 1) + ")" : "").append('\n');
        for (StepRecord s : steps) {
            b.append(String.format("step %d/%d (line %d) %s: %s in %.1f s%n", s.index() + 1, s.total(), s.line(), s.step(),
                    s.verdict(), (s.ended() - s.started()) / 1000.0));
            for (FileRecord f : s.files()) {
                b.append("  file ").append(f.name()).append(' ').append(f.size()).append(" bytes sha256 ").append(f.sha256())
                        .append('\n');
            }
            if (!s.error().isEmpty()) {
                b.append("  error: ").append(s.error().replace("\n", "\n         ")).append('\n');
            }
            if (outputs && !s.output().isEmpty()) {
                b.append("  output: ").append(s.output().replace("\n", "\n          ")).append('\n');
            }
        }
        if (tally != null) {
            b.append("done: ").append(tally.describe()).append('\n');
        }
        b.append("result: ").append(result);
        if (ended > 0) {
            b.append(" at ").append(Instant.ofEpochMilli(ended)).append(String.format(" (%.1f s)", (ended - started) / 1000.0));
        }
        b.append('\n');
        if (!error.isEmpty()) {
            b.append("error: ").append(error).append('\n');
        }
        return b.toString();
    }
}
