package org.ripv.dac;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * One run of the pipeline over a set of files: decode, split, derive, flag, write, check. All
 * segments are decoded and split before the first file is written, so input that is refused
 * leaves nothing behind; a file is checked before it takes its name, and one that fails is kept
 * as {@code NAME.failed} and reported, never given the name a DAC upload would pick up.
 */
public record DacRun(SegmentReader reader, ProfileSplitter splitter, ProfileWriter writer, ProfileChecker checker) {
    /** What was written, one line a profile, and whether every file passed the check. */
    public record Result(List<Path> written, List<String> lines, boolean allPassed, List<Made> made) {
    }

    /** One profile's file: where it is ({@code NAME.failed} when it failed the check), its check, its QC summary and line. */
    public record Made(Profile profile, Path file, ProfileChecker.Report report, String qc, String line) {
    }

    public Result run(List<Path> files, Path out) throws DacException, IOException {
        List<Profile> all = new ArrayList<>();
        for (Segment s : reader.read(files)) {
            all.addAll(Profiles.of(s, splitter));
        }
        List<Path> written = new ArrayList<>();
        List<String> lines = new ArrayList<>();
        List<Made> made = new ArrayList<>();
        boolean ok = true;
        for (Profile p : all) {
            ProfileChecker.Report[] report = new ProfileChecker.Report[1];
            Path f = writer.write(p, out, checker, report);
            ProfileChecker.Report r = report[0];
            String qc = qcSummary(writer.flags(p));
            if (r.passed()) {
                written.add(f);
                lines.add(String.format(java.util.Locale.ROOT, "%s: %s, %d samples, %.1f to %.1f dbar%s%s", f.getFileName(),
                        p.direction() > 0 ? "dive" : "climb", p.size(), p.pressure()[0], p.pressure()[p.size() - 1], qc,
                        r.warnings().isEmpty() ? "" : " (warnings: " + String.join("; ", r.warnings()) + ")"));
            } else {
                ok = false;
                lines.add(f.getFileName() + ": FAILS the DAC check, kept, not for sending: " + String.join("; ", r.failures()));
            }
            made.add(new Made(p, f, r, qc, lines.get(lines.size() - 1)));
        }
        if (all.isEmpty()) {
            lines.add("no profile: no dive or climb spans more than the minimum depth with enough samples");
        }
        return new Result(written, lines, ok, made);
    }

    /** ", QC temperature 120 good 3 suspect ..." from the primary flags. */
    static String qcSummary(Map<String, Map<String, byte[]>> flags) {
        if (flags.isEmpty()) {
            return ", no QC configured";
        }
        StringBuilder sb = new StringBuilder(", QC");
        for (Map.Entry<String, Map<String, byte[]>> e : flags.entrySet()) {
            int[] c = new int[10];
            for (byte b : e.getValue().get("primary")) {
                c[b]++;
            }
            sb.append(' ').append(e.getKey()).append(' ').append(c[1]).append(" good");
            if (c[3] > 0) {
                sb.append(' ').append(c[3]).append(" suspect");
            }
            if (c[4] > 0) {
                sb.append(' ').append(c[4]).append(" fail");
            }
            if (c[9] > 0) {
                sb.append(' ').append(c[9]).append(" missing");
            }
            if (c[2] > 0) {
                sb.append(' ').append(c[2]).append(" not evaluated");
            }
            sb.append(';');
        }
        sb.setLength(sb.length() - 1);
        return sb.toString();
    }
}
