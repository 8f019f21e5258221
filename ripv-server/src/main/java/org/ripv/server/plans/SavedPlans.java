package org.ripv.server.plans;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.NoSuchFileException;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.TableResult;
import org.ripv.plans.BehaviorFileReader;
import org.ripv.plans.PlanCheck;
import org.ripv.plans.PlanLimits;
import org.ripv.plans.PlanTable;

/**
 * {@code ?plan MAILBOX save FILE [as NAME]} and {@code ?plan MAILBOX history NAME [N]}: the kept
 * versions of a behaviour file, each with its diff against the last version that was sent.
 */
record SavedPlans(PlanVersions versions, ChangeBook book, PlanFiles files, PlanRights rights, PlanLimits limits) {
    /**
     * Checks FILE and keeps it as the next version of NAME (who, when), with the diff against the
     * last version of NAME that was sent. A refused file is no version.
     */
    OutgoingServerMessage save(IncomingServerMessage request, String mailbox, String name, String as) throws IOException {
        String user = request.header().origin().user();
        rights.permitted(request);
        PlanFiles.vehicleName(as);
        PlanFiles.Found f = files.find(mailbox, name);
        byte[] bytes = files.readBounded(f);
        PlanCheck c = BehaviorFileReader.check(name, bytes, limits);
        if (!c.ok()) {
            return PlanCommands.error(request, Ids.FID_PLAN, ErrorCode.BAD_REQUEST, PlanFiles.refusal(c, f) + "; no version was kept");
        }
        PlanVersions.Version v = versions.save(mailbox, as, user, bytes, c.file().sha256());
        for (Change sent : book.of(mailbox)) { // these very bytes went before: the version says so
            if (sent.kind() == Change.Kind.FILE && sent.state() != Change.State.CANCELLED && sent.sha256().equals(v.sha256())) {
                versions.sent(mailbox, v.sha256(), sentAs(sent));
            }
        }
        return PlanCommands.ok(request, Ids.FID_PLAN, "version " + v.n() + " of " + as + " for " + mailbox + ", saved by " + user + " at "
                + Instant.ofEpochMilli(v.time()) + " from " + name + "\n" + PlanTable.summary(c.file()) + "\n"
                + diffText(mailbox, as, v, bytes), PlanFiles.table(c.file()));
    }

    /** The versions of NAME, and the diff of version N (the newest when not given) against the last sent before it. */
    OutgoingServerMessage history(IncomingServerMessage request, String mailbox, String as, String nText) throws IOException {
        PlanFiles.vehicleName(as);
        List<PlanVersions.Version> all = versions.list(mailbox, as);
        if (all.isEmpty()) {
            throw new NoSuchFileException("no saved version of " + as + " for " + mailbox + " (?plan " + mailbox + " save FILE as "
                    + as + " keeps one)");
        }
        PlanVersions.Version of = all.get(all.size() - 1);
        if (nText != null) {
            PlanCommands.need(nText.matches("\\d{1,9}"), "usage: ?plan MAILBOX history NAME [N]: N is a version number");
            int n = Integer.parseInt(nText);
            of = all.stream().filter(v -> v.n() == n).findFirst().orElseThrow(() -> new IllegalArgumentException(
                    "no version " + n + " of " + as + " is kept (versions " + all.get(0).n() + " to " + all.get(all.size() - 1).n() + ")"));
        }
        StringBuilder b = new StringBuilder(all.size() + " version(s) of " + as + " for " + mailbox + "\n");
        List<String[]> rows = new ArrayList<>();
        for (PlanVersions.Version v : all) {
            String saved = Instant.ofEpochMilli(v.time()).toString();
            rows.add(new String[] {Integer.toString(v.n()), saved, v.user(), v.sha256(), Long.toString(v.bytes()), v.sent()});
            b.append(String.format(Locale.ROOT, "%4d  %s  %-12s %s%n", v.n(), saved, v.user(),
                    v.sent().isEmpty() ? "not sent" : "sent " + v.sent()));
        }
        b.append("version ").append(of.n()).append(": ").append(diffText(mailbox, as, of, versions.bytes(mailbox, as, of.n())));
        return PlanCommands.ok(request, Ids.FID_PLAN, b.toString(), new TableResult("?plan history " + as, List.of("version", "saved", "user",
                "sha256", "bytes", "sent"), List.of("INTEGER", "VARCHAR", "VARCHAR", "VARCHAR", "INTEGER", "VARCHAR"), rows, false));
    }

    static String sentAs(Change c) {
        return "as " + c.target() + ", change " + c.id() + ", " + Instant.ofEpochMilli(c.queuedAt()) + " by " + c.user();
    }

    private String diffText(String mailbox, String as, PlanVersions.Version v, byte[] bytes) throws IOException {
        Optional<PlanVersions.Version> sent = versions.lastSentBefore(mailbox, as, v.n());
        if (sent.isEmpty()) {
            return "no earlier version of " + as + " was sent: all of it is new";
        }
        List<String> diff = LineDiff.diff(lines(versions.bytes(mailbox, as, sent.get().n())), lines(bytes));
        long changed = diff.stream().filter(l -> !l.startsWith("  ")).count();
        return "diff against version " + sent.get().n() + ", the last sent (" + sent.get().sent() + "): " + changed
                + " line(s) differ\n" + String.join("\n", diff);
    }

    private static List<String> lines(byte[] bytes) {
        return new String(bytes, StandardCharsets.ISO_8859_1).lines().toList();
    }
}
