package org.ripv.server.plans;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Instant;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.plans.SurfacingFacts;
import org.ripv.server.files.FileStore;
import org.ripv.surfacing.SurfaceDialogParser;
import org.ripv.surfacing.Surfacing;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Moves changes along by what the console shows. A file is <b>sent</b> when the to-vehicle round
 * moved it to {@code sent/} with its receipt, and <b>received</b> when that round's check of the
 * vehicle's {@code dir} listed it with its size; a {@code put} is sent when its workflow is done
 * and received when the vehicle echoed {@code sensor:NAME=VALUE}. A surfacing that began after
 * that decides: <b>in effect</b> when its dialog's {@code c_wpt_lat/lon} is one of the goto file's
 * waypoints, or its {@code sensor:NAME} shows the value; after {@value #SURFACINGS} surfacings
 * without, <b>not in effect</b> and an ALERT. Runs on the plans thread only.
 */
final class ChangeFollower {
    private static final Logger log = LoggerFactory.getLogger(ChangeFollower.class);
    /** Surfacings that may pass without showing a change before it is not in effect. */
    static final int SURFACINGS = 2;
    /** How close a dialog's waypoint must be to a file's: 2e-4° is 22 m, far above the dialog's 0.001' rounding. */
    static final double WAYPOINT_DEGREES = 2e-4;
    /** Sensor lines kept per call (a put's echo among them). */
    static final int MAX_SENSORS = 500;
    private static final Pattern SENT = Pattern.compile("to-vehicle: sent (\\S+) \\(.*; moved to (to-vehicle/[^ ]+/sent/[^ ]+) \\(receipt.*",
            Pattern.DOTALL);
    private static final Pattern WORKFLOW = Pattern.compile("workflow (\\d+) '.*", Pattern.DOTALL);

    private final ChangeBook book;
    private final FileStore files;
    private final Consumer<ConsoleEntry> publish;
    /** Per MailBox, the {@code sensor:} lines of its current call (a put's echo among them). */
    private final Map<String, Map<String, Double>> echoes = new HashMap<>();

    ChangeFollower(ChangeBook book, FileStore files, Consumer<ConsoleEntry> publish) {
        this.book = book;
        this.files = files;
        this.publish = publish;
    }

    void take(ConsoleEntry e) {
        try {
            switch (e.kind()) {
                case EVENT -> event(e);
                case LINE -> line(e);
                case COMMAND -> command(e);
                default -> { }
            }
        } catch (IOException x) {
            log.warn("{}: could not record a change's progress: {}", e.mailbox(), x.toString());
        }
    }

    private void event(ConsoleEntry e) throws IOException {
        VehicleEvent ev = e.event();
        if (ev == VehicleEvent.SURFACED) {
            echoes.put(e.mailbox(), new HashMap<>());
            sweep(e.mailbox());
        } else if (ev == VehicleEvent.DIVED || ev == VehicleEvent.LINK_LOST) {
            echoes.remove(e.mailbox());
            sweep(e.mailbox());
        } else if (ev == VehicleEvent.WORKFLOW_DONE || ev == VehicleEvent.WORKFLOW_FAILED
                || ev == VehicleEvent.WORKFLOW_DONE_WITH_ERRORS) {
            Matcher m = WORKFLOW.matcher(e.text());
            if (!m.matches()) {
                return;
            }
            long id = Long.parseLong(m.group(1));
            for (Change c : book.of(e.mailbox())) {
                if (c.kind() != Change.Kind.SET || c.workflowId() != id || c.state() != Change.State.QUEUED) {
                    continue;
                }
                if (ev == VehicleEvent.WORKFLOW_DONE) {
                    Change sent = move(c, Change.State.SENT, e.time(), "workflow " + id + " sent 'put " + c.target() + " "
                            + c.value() + "' (?receipts " + c.mailbox() + ")");
                    Double echo = echoes.getOrDefault(e.mailbox(), Map.of()).get(c.target());
                    if (echo != null && same(echo, c.value())) {
                        move(sent, Change.State.RECEIVED, e.time(), "the vehicle echoed sensor:" + c.target() + "=" + c.value());
                    }
                } else {
                    book.put(c.withDetail("workflow " + id + " failed (" + e.text() + "); it tries again on the next call"));
                }
            }
        }
    }

    private void line(ConsoleEntry e) throws IOException {
        Surfacing.Sensor s = SurfaceDialogParser.sensorLine(e.text()).orElse(null);
        if (s == null || s.value() == null) {
            return;
        }
        String name = s.name().toLowerCase(Locale.ROOT);
        Map<String, Double> call = echoes.get(e.mailbox());
        if (call != null && call.size() < MAX_SENSORS) {
            call.put(name, s.value());
        }
        for (Change c : book.of(e.mailbox())) {
            if (c.kind() == Change.Kind.SET && c.state() == Change.State.SENT && c.target().equals(name) && same(s.value(), c.value())) {
                move(c, Change.State.RECEIVED, e.time(), "the vehicle echoed sensor:" + name + "=" + c.value());
            }
        }
    }

    private void command(ConsoleEntry e) throws IOException {
        Matcher m = SENT.matcher(e.text());
        if (!m.matches()) {
            return;
        }
        String name = m.group(1);
        String sentAs = m.group(2);
        String staged = sentAs.substring(0, sentAs.indexOf("/sent/")) + "/" + name;
        for (Change c : book.of(e.mailbox())) {
            if (c.kind() != Change.Kind.FILE || c.state() != Change.State.QUEUED || !c.staged().equals(staged)) {
                continue;
            }
            String sha = sha256(files.uploadDir().resolve(sentAs));
            if (!sha.equals(c.sha256())) {
                move(c, Change.State.CANCELLED, e.time(), "the staged file was replaced after ?plan send: the vehicle got " + sentAs
                        + " (sha256 " + sha + "), not the file checked (sha256 " + c.sha256() + "); that file is not followed");
                return;
            }
            String differs = "";
            Change sent = move(c, Change.State.SENT, e.time(), "sent by the to-vehicle round: " + sentAs + ".receipt, sha256 " + sha
                    + differs);
            if (e.text().contains("dir lists " + name + " with ")) {
                move(sent, Change.State.RECEIVED, e.time(), "the vehicle's dir lists " + name + " with its size; sha256 " + sha
                        + differs + " (receipt " + sentAs + ".receipt)");
            }
            return; // one staged file is one change
        }
    }

    /**
     * Queued files of {@code mailbox} (every MailBox when null) whose staged copy is gone, or is
     * no longer the file that was checked, are cancelled: the to-vehicle round can only send what
     * is in the folder, so the change as checked never reaches the vehicle. A file the round has
     * just moved to {@code sent/} (its receipt names it, written after the change was queued) is
     * left for the round's own line.
     */
    void sweep(String mailbox) {
        try {
            for (Change c : mailbox == null ? book.list(x -> true) : book.of(mailbox)) {
                if (c.kind() != Change.Kind.FILE || c.state() != Change.State.QUEUED || c.staged().isEmpty()) {
                    continue;
                }
                Path staged = files.uploadDir().resolve(c.staged());
                long now = System.currentTimeMillis();
                if (!Files.isRegularFile(staged)) {
                    if (!sentSince(c, staged)) {
                        move(c, Change.State.CANCELLED, now, "the staged file " + c.staged() + " was deleted before a call took it;"
                                + " nothing of this change goes to the vehicle");
                    }
                    continue;
                }
                String sha = sha256(staged);
                if (!sha.equals(c.sha256())) {
                    move(c, Change.State.CANCELLED, now, "the staged file " + c.staged() + " was replaced (sha256 " + sha
                            + ", not the file checked, sha256 " + c.sha256() + "): the new file goes unchecked and is not followed;"
                            + " ?plan send it to follow it");
                }
            }
        } catch (IOException x) {
            log.warn("could not look at the staged files of {}: {}", mailbox == null ? "the fleet" : mailbox, x.toString());
        }
    }

    /** True when a receipt in the staged file's {@code sent/} folder, written since it was queued, names it. */
    private static boolean sentSince(Change c, Path staged) {
        Path sent = staged.getParent().resolve("sent");
        if (!Files.isDirectory(sent)) {
            return false;
        }
        String line = "file: " + c.staged() + "\n";
        try (var list = Files.newDirectoryStream(sent, "*.receipt")) {
            int looked = 0;
            for (Path r : list) {
                if (++looked > 2000) {
                    return true; // too many to look through: leave it to the round's line rather than cancel wrongly
                }
                if (Files.getLastModifiedTime(r).toMillis() + 2000 >= c.queuedAt() && Files.size(r) < 64 * 1024
                        && Files.readString(r).startsWith(line)) {
                    return true;
                }
            }
        } catch (IOException | RuntimeException e) {
            return false;
        }
        return false;
    }

    /** A surfacing's dialog: the changes it can show are judged by it. */
    void judge(SurfacingFacts f) {
        try {
            for (Change c : book.of(f.mailbox())) {
                if (c.state() != Change.State.SENT && c.state() != Change.State.RECEIVED) {
                    continue;
                }
                long got = c.receivedAt() > 0 ? c.receivedAt() : c.sentAt();
                if (got >= f.time()) {
                    continue; // the glider had not got it when this surfacing began
                }
                String shown = shows(c, f);
                if (shown == null) {
                    continue; // a file whose effect no dialog shows (a yo or surface file)
                }
                String when = Instant.ofEpochMilli(f.time()).toString();
                if (!shown.isEmpty()) {
                    move(c, Change.State.IN_EFFECT, System.currentTimeMillis(), "the surfacing at " + when + " shows it: " + shown);
                    continue;
                }
                int n = c.surfacings() + 1;
                String why = "the surfacing at " + when + " did not show it (" + seen(c, f) + ")";
                if (n >= SURFACINGS) {
                    Change late = move(c.withSurfacings(n, why), Change.State.NOT_IN_EFFECT, System.currentTimeMillis(),
                            n + " surfacings without it; last: " + why);
                    publish.accept(ConsoleEntry.event(c.mailbox(), VehicleEvent.ALERT, "change " + c.id() + " " + c.what()
                            + " is not in effect: " + late.detail(), null, null));
                } else {
                    book.put(c.withSurfacings(n, why + "; " + n + " of " + SURFACINGS));
                }
            }
        } catch (IOException x) {
            log.warn("{}: could not record a surfacing's verdict: {}", f.mailbox(), x.toString());
        }
    }

    /** What of {@code c} the dialog shows ("" for nothing), or null when a dialog cannot show it. */
    private static String shows(Change c, SurfacingFacts f) {
        if (c.kind() == Change.Kind.SET) {
            Double v = f.sensors().get(c.target());
            return v != null && same(v, c.value()) ? "sensor:" + c.target() + "=" + fmt(v) : "";
        }
        if (c.waypoints().isEmpty()) {
            return null;
        }
        if (f.wptLat() == null || f.wptLon() == null) {
            return "";
        }
        for (int i = 0; i < c.waypoints().size(); i++) {
            double[] w = c.waypoints().get(i);
            if (Math.abs(w[0] - f.wptLat()) <= WAYPOINT_DEGREES && Math.abs(w[1] - f.wptLon()) <= WAYPOINT_DEGREES) {
                return String.format(Locale.ROOT, "c_wpt_lat/lon %.5f, %.5f is waypoint %d", f.wptLat(), f.wptLon(), i);
            }
        }
        return "";
    }

    private static String seen(Change c, SurfacingFacts f) {
        if (c.kind() == Change.Kind.SET) {
            Double v = f.sensors().get(c.target());
            return v == null ? "no sensor:" + c.target() + " in its dialog (report ++ " + c.target() + " shows it)"
                    : "sensor:" + c.target() + "=" + fmt(v) + ", not " + c.value();
        }
        return f.wptLat() == null ? "no c_wpt_lat/lon in its dialog (report ++ c_wpt_lat, report ++ c_wpt_lon shows them)"
                : String.format(Locale.ROOT, "c_wpt_lat/lon %.5f, %.5f is none of the file's %d waypoints", f.wptLat(), f.wptLon(),
                c.waypoints().size());
    }

    private Change move(Change c, Change.State to, long at, String why) throws IOException {
        Change next = c.moved(to, at, why);
        book.put(next);
        publish.accept(ConsoleEntry.event(c.mailbox(), VehicleEvent.PLAN_CHANGE, "change " + c.id() + " " + c.what() + ": "
                + to.word() + ": " + why, null, null));
        if (to == Change.State.RECEIVED) {
            // an older change of the same file or parameter the vehicle now has a newer one of can no longer show
            for (Change old : book.of(c.mailbox())) {
                if (old.id() < c.id() && old.kind() == c.kind() && old.target().equalsIgnoreCase(c.target())
                        && (old.state() == Change.State.SENT || old.state() == Change.State.RECEIVED)) {
                    Change replaced = old.moved(Change.State.NOT_IN_EFFECT, at, "replaced by change " + c.id() + " before it showed");
                    book.put(replaced);
                    publish.accept(ConsoleEntry.event(c.mailbox(), VehicleEvent.PLAN_CHANGE, "change " + old.id() + " " + old.what()
                            + ": not in effect: " + replaced.detail(), null, null));
                }
            }
        }
        return next;
    }

    static boolean same(double v, String value) {
        double want;
        try {
            want = Double.parseDouble(value);
        } catch (NumberFormatException e) {
            return false;
        }
        return Math.abs(v - want) <= 1e-6 * Math.max(1.0, Math.abs(want));
    }

    private static String fmt(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    static String sha256(Path p) {
        try (InputStream in = Files.newInputStream(p)) {
            MessageDigest d = MessageDigest.getInstance("SHA-256");
            byte[] buf = new byte[8192];
            for (int n; (n = in.read(buf)) > 0; ) {
                d.update(buf, 0, n);
            }
            return HexFormat.of().formatHex(d.digest());
        } catch (IOException e) {
            return "unreadable (" + e.getMessage() + ")";
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
