package org.ripv.server.plans;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Pattern;

import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Result;
import org.ripv.messages.TableResult;
import org.ripv.messages.VehicleEvent;
import org.ripv.messages.ConsoleEntry;
import org.ripv.naming.MailboxAddress;
import org.ripv.plans.BehaviorFile;
import org.ripv.plans.BehaviorFileReader;
import org.ripv.plans.Forecast;
import org.ripv.plans.PlanCheck;
import org.ripv.plans.PlanLimits;
import org.ripv.plans.PlanTable;
import org.ripv.plans.Waypoint;
import org.ripv.server.files.FileExistsException;
import org.ripv.server.files.FileNames;
import org.ripv.server.files.FileStore;
import org.ripv.server.files.ToVehicleFolder;
import org.ripv.server.files.UploadMode;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.session.Rights;

/**
 * {@code ?plan MAILBOX check FILE}, {@code ?plan MAILBOX send FILE [as NAME]},
 * {@code ?plan MAILBOX set NAME VALUE} and {@code ?changes [MAILBOX]}. Rights: the read right on
 * the MailBox for all of them; {@code send} and {@code set} also a permit rule allowing the
 * command on RIPVServer ({@code ?plan *}), {@code send} the right {@code ?to-vehicle FOLDER} an
 * upload to the folder needs, {@code set} the right to send {@code put NAME VALUE} to the MailBox.
 */
final class PlanCommands {
    static final String SERVER = "RIPVServer";
    /** A name the glider's FAT file system takes: 8.3, a behaviour file's {@code .ma}. */
    private static final Pattern VEHICLE_NAME = Pattern.compile("[A-Za-z0-9_-]{1,8}\\.[Mm][Aa]");
    private static final Pattern SENSOR = Pattern.compile("[a-z][a-z0-9_]{0,39}");
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d{1,15}(\\.\\d{0,15})?|\\.\\d{1,15})([eE][+-]?\\d{1,3})?");

    private final PlanHost host;
    private final ChangeBook book;
    private final PlanLimits limits;
    private final Fixes fixes;
    private final PlanVersions versions;
    /** A Slocum's usual horizontal speed through the water, for a glider with fewer than two fixes. */
    static final double ASSUMED_SPEED = 0.3;

    PlanCommands(PlanHost host, ChangeBook book, PlanLimits limits, Fixes fixes, PlanVersions versions) {
        this.versions = versions;
        this.host = host;
        this.book = book;
        this.limits = limits;
        this.fixes = fixes;
    }

    /** A refusal by the rights: answered FORBIDDEN. */
    static final class Refused extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Refused(String message) {
            super(message);
        }
    }

    OutgoingServerMessage plan(IncomingServerMessage request) throws IOException {
        String[] w = request.header().body().trim().split("\\s+");
        String usage = "usage: ?plan MAILBOX check FILE | ?plan MAILBOX send FILE [as NAME] | ?plan MAILBOX set NAME VALUE"
                + " | ?plan MAILBOX forecast FILE [SPEED] | ?plan MAILBOX save FILE [as NAME] | ?plan MAILBOX history NAME [N]"
                + " | ?plan MAILBOX current";
        if (w.length == 3 && w[2].equalsIgnoreCase("current")) {
            String mailbox = address(w[1]);
            mayRead(request.header().origin().user(), mailbox);
            return current(request, mailbox);
        }
        if (w.length < 4) {
            throw new IllegalArgumentException(usage);
        }
        String mailbox = address(w[1]);
        String user = request.header().origin().user();
        mayRead(user, mailbox);
        return switch (w[2].toLowerCase(Locale.ROOT)) {
            case "check" -> {
                need(w.length == 4, "usage: ?plan MAILBOX check FILE");
                yield check(request, mailbox, w[3]);
            }
            case "send" -> {
                need(w.length == 4 || (w.length == 6 && w[4].equalsIgnoreCase("as")), "usage: ?plan MAILBOX send FILE [as NAME]");
                yield send(request, mailbox, w[3], w.length == 6 ? w[5] : w[3]);
            }
            case "set" -> {
                need(w.length == 5, "usage: ?plan MAILBOX set NAME VALUE");
                yield set(request, mailbox, w[3], w[4]);
            }
            case "forecast" -> {
                need(w.length == 4 || w.length == 5, "usage: ?plan MAILBOX forecast FILE [SPEED] (m/s through the water)");
                yield forecast(request, mailbox, w[3], w.length == 5 ? w[4] : null);
            }
            case "save" -> {
                need(w.length == 4 || (w.length == 6 && w[4].equalsIgnoreCase("as")), "usage: ?plan MAILBOX save FILE [as NAME]");
                yield save(request, mailbox, w[3], w.length == 6 ? w[5] : w[3]);
            }
            case "history" -> {
                need(w.length == 4 || w.length == 5, "usage: ?plan MAILBOX history NAME [N]");
                yield history(request, mailbox, w[3], w.length == 5 ? w[4] : null);
            }
            default -> throw new IllegalArgumentException(usage);
        };
    }

    /**
     * Checks FILE and keeps it as the next version of NAME (who, when), with the diff against the
     * last version of NAME that was sent. A refused file is no version.
     */
    private OutgoingServerMessage save(IncomingServerMessage request, String mailbox, String name, String as) throws IOException {
        String user = request.header().origin().user();
        permitted(request);
        vehicleName(as);
        Found f = find(mailbox, name);
        byte[] bytes = readBounded(f);
        PlanCheck c = BehaviorFileReader.check(name, bytes, limits);
        if (!c.ok()) {
            return error(request, Ids.FID_PLAN, ErrorCode.BAD_REQUEST, refusal(c, f) + "; no version was kept");
        }
        PlanVersions.Version v = versions.save(mailbox, as, user, bytes, c.file().sha256());
        for (Change sent : book.of(mailbox)) { // these very bytes went before: the version says so
            if (sent.kind() == Change.Kind.FILE && sent.state() != Change.State.CANCELLED && sent.sha256().equals(v.sha256())) {
                versions.sent(mailbox, v.sha256(), sentAs(sent));
            }
        }
        return ok(request, Ids.FID_PLAN, "version " + v.n() + " of " + as + " for " + mailbox + ", saved by " + user + " at "
                + Instant.ofEpochMilli(v.time()) + " from " + name + "\n" + PlanTable.summary(c.file()) + "\n"
                + diffText(mailbox, as, v, bytes), table(c.file()));
    }

    /** The versions of NAME, and the diff of version N (the newest when not given) against the last sent before it. */
    private OutgoingServerMessage history(IncomingServerMessage request, String mailbox, String as, String nText) throws IOException {
        vehicleName(as);
        List<PlanVersions.Version> all = versions.list(mailbox, as);
        if (all.isEmpty()) {
            throw new NoSuchFileException("no saved version of " + as + " for " + mailbox + " (?plan " + mailbox + " save FILE as "
                    + as + " keeps one)");
        }
        PlanVersions.Version of = all.get(all.size() - 1);
        if (nText != null) {
            need(nText.matches("\\d{1,9}"), "usage: ?plan MAILBOX history NAME [N]: N is a version number");
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
        return ok(request, Ids.FID_PLAN, b.toString(), new TableResult("?plan history " + as, List.of("version", "saved", "user",
                "sha256", "bytes", "sent"), List.of("INTEGER", "VARCHAR", "VARCHAR", "VARCHAR", "INTEGER", "VARCHAR"), rows, false));
    }

    private static String sentAs(Change c) {
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

    private byte[] readBounded(Found f) throws IOException {
        try (InputStream in = Files.newInputStream(f.path())) {
            return in.readNBytes(limits.maxBytes() + 1);
        }
    }

    private static void vehicleName(String as) {
        if (!VEHICLE_NAME.matcher(as).matches()) {
            throw new IllegalArgumentException("'" + as + "' is not a name for the glider: behaviour files are NAME.ma with"
                    + " NAME 1 to 8 letters, digits, '_' or '-' (its file system takes 8.3 names), e.g. goto_l10.ma");
        }
    }

    /**
     * The goto list the glider runs as far as the shore knows: of the goto file in effect (the
     * newest change shown in effect) and the newest {@code goto_l*.ma} fetched from it, the later;
     * with the waypoint its last dialog steered for and its last fix.
     */
    private OutgoingServerMessage current(IncomingServerMessage request, String mailbox) throws IOException {
        List<String[]> rows = new ArrayList<>();
        StringBuilder b = new StringBuilder();
        Change inEffect = null;
        for (Change c : book.of(mailbox)) {
            if (c.kind() == Change.Kind.FILE && c.state() == Change.State.IN_EFFECT && !c.waypoints().isEmpty()) {
                inEffect = c;
            }
        }
        Path fetched = newestGotoFile(mailbox);
        long fetchedAt = fetched == null ? 0 : Files.getLastModifiedTime(fetched).toMillis();
        if (fetched != null && (inEffect == null || fetchedAt > inEffect.settledAt())) {
            PlanCheck c;
            try (InputStream in = Files.newInputStream(fetched)) {
                c = BehaviorFileReader.check(fetched.getFileName().toString(), in, limits);
            }
            if (c.ok()) {
                b.append("goto list: ").append(fetched.getFileName()).append(", fetched from the vehicle at ")
                        .append(Instant.ofEpochMilli(fetchedAt)).append('\n');
                for (Waypoint wp : c.file().waypoints()) {
                    rows.add(row("waypoint", Integer.toString(wp.n()), wp.lat(), wp.lon(), wp.comment()));
                }
            } else {
                b.append("goto list: ").append(fetched.getFileName()).append(", fetched, does not pass the check (?plan ")
                        .append(mailbox).append(" check ").append(fetched.getFileName()).append(")\n");
            }
        }
        if (rows.isEmpty() && inEffect != null) {
            b.append("goto list: ").append(inEffect.target()).append(", change ").append(inEffect.id()).append(", in effect since ")
                    .append(Instant.ofEpochMilli(inEffect.settledAt())).append('\n');
            for (int i = 0; i < inEffect.waypoints().size(); i++) {
                double[] w = inEffect.waypoints().get(i);
                rows.add(row("waypoint", Integer.toString(i), w[0], w[1], ""));
            }
        }
        if (rows.isEmpty() && b.length() == 0) {
            b.append("goto list: none known (no goto_l*.ma fetched from the vehicle, no goto file in effect)\n");
        }
        fixes.heading(mailbox).ifPresentOrElse(h -> {
            rows.add(row("heading", "", h.lat(), h.lon(), "c_wpt_lat/lon of the dialog at " + Instant.ofEpochMilli(h.time())));
            b.append(String.format(Locale.ROOT, "heading for %.5f, %.5f (c_wpt_lat/lon of the dialog at %s)%n", h.lat(), h.lon(),
                    Instant.ofEpochMilli(h.time())));
        }, () -> b.append("heading for: no c_wpt_lat/lon in a dialog since the server started\n"));
        fixes.last(mailbox).ifPresent(fx -> {
            rows.add(row("fix", "", fx.lat(), fx.lon(), Instant.ofEpochMilli(fx.time()).toString()));
            b.append(String.format(Locale.ROOT, "last fix %.5f, %.5f at %s%n", fx.lat(), fx.lon(), Instant.ofEpochMilli(fx.time())));
        });
        return ok(request, Ids.FID_PLAN, b.toString().strip(), new TableResult("?plan current", List.of("kind", "n", "lat", "lon",
                "comment"), List.of("VARCHAR", "VARCHAR", "DOUBLE", "DOUBLE", "VARCHAR"), rows, false));
    }

    private static String[] row(String kind, String n, double lat, double lon, String comment) {
        return new String[] {kind, n, String.format(Locale.ROOT, "%.5f", lat), String.format(Locale.ROOT, "%.5f", lon), comment};
    }

    private static final Pattern GOTO_FILE = Pattern.compile("(?i)goto_l\\d{1,3}\\.ma");

    /** The newest goto_l*.ma among the vehicle's downloads (at most 10,000 names looked at). */
    private Path newestGotoFile(String mailbox) throws IOException {
        Path folder = host.files().downloadDir().resolve(FileStore.folderFor(mailbox));
        if (!Files.isDirectory(folder)) {
            return null;
        }
        Path newest = null;
        long at = Long.MIN_VALUE;
        int looked = 0;
        try (DirectoryStream<Path> files = Files.newDirectoryStream(folder)) {
            for (Path p : files) {
                if (++looked > 10_000) {
                    break;
                }
                if (GOTO_FILE.matcher(p.getFileName().toString()).matches() && Files.isRegularFile(p)) {
                    long t = Files.getLastModifiedTime(p).toMillis();
                    if (t > at) {
                        at = t;
                        newest = p;
                    }
                }
            }
        }
        return newest;
    }

    /**
     * Distance, bearing and ETA to each waypoint from the vehicle's last fix. The speed through
     * the water is the pilot's, else the last two fixes' speed over ground less the current, else
     * {@value #ASSUMED_SPEED} m/s; the current is the last dialog's {@code m_water_vx/vy}.
     */
    private OutgoingServerMessage forecast(IncomingServerMessage request, String mailbox, String name, String speedText)
            throws IOException {
        Found f = find(mailbox, name);
        PlanCheck c = read(f, name);
        if (!c.ok()) {
            return error(request, Ids.FID_PLAN, ErrorCode.BAD_REQUEST, refusal(c, f));
        }
        if (!c.file().isGoto()) {
            throw new IllegalArgumentException(name + " is a " + c.file().behavior() + " file: only a goto list has waypoints to forecast");
        }
        Fixes.Fix fix = fixes.last(mailbox).orElseThrow(() -> new IllegalArgumentException("no GPS fix of " + mailbox
                + " since the server started: a forecast starts from the last surfacing's position"));
        Fixes.Current cur = fixes.current(mailbox).orElse(new Fixes.Current(0, 0));
        String currentWhy = fixes.current(mailbox).isPresent()
                ? String.format(Locale.ROOT, "depth-averaged current %.3f m/s east, %.3f m/s north (the last dialog's m_water_vx/vy)",
                cur.east(), cur.north()) : "no current known (m_water_vx/vy not in the dialogs)";
        double speed;
        String speedWhy;
        if (speedText != null) {
            if (!NUMBER.matcher(speedText).matches() || !(Double.parseDouble(speedText) > 0) || Double.parseDouble(speedText) > 5) {
                throw new IllegalArgumentException("SPEED is the glider's speed through the water in m/s, over 0 and at most 5, not '"
                        + speedText + "'");
            }
            speed = Double.parseDouble(speedText);
            speedWhy = "speed " + speedText + " m/s (given)";
        } else {
            Fixes.Fix before = fixes.previous(mailbox).orElse(null);
            double seconds = before == null ? 0 : (fix.time() - before.time()) / 1000.0;
            if (before != null && seconds >= 60) {
                double d = Forecast.distance(before.lat(), before.lon(), fix.lat(), fix.lon());
                double b = Math.toRadians(Forecast.bearing(before.lat(), before.lon(), fix.lat(), fix.lon()));
                double east = d / seconds * Math.sin(b) - cur.east();
                double north = d / seconds * Math.cos(b) - cur.north();
                speed = Math.hypot(east, north);
                speedWhy = String.format(Locale.ROOT, "speed %.3f m/s through the water (%.3f m/s over ground between the last two"
                        + " fixes, less the current)", speed, d / seconds);
            } else {
                speed = 0;
                speedWhy = "";
            }
            if (!(speed > 0.05)) {
                speed = ASSUMED_SPEED;
                speedWhy = "speed " + ASSUMED_SPEED + " m/s (assumed: fewer than two fixes a minute apart, or no way made)";
            }
        }
        List<Forecast.Leg> legs = Forecast.legs(c.file(), fix.lat(), fix.lon(),
                Instant.ofEpochMilli(fix.time()), speed, cur.east(), cur.north());
        String basis = String.format(Locale.ROOT, "of %s for %s from its fix at %s (%.5f, %.5f); %s; %s", name, mailbox,
                Instant.ofEpochMilli(fix.time()), fix.lat(), fix.lon(), speedWhy, currentWhy);
        List<String[]> rows = new ArrayList<>();
        for (Forecast.Leg l : legs) {
            rows.add(new String[] {Integer.toString(l.n()), String.format(Locale.ROOT, "%.5f", l.lat()),
                    String.format(Locale.ROOT, "%.5f", l.lon()), String.format(Locale.ROOT, "%.1f", l.legMetres()),
                    String.format(Locale.ROOT, "%.1f", l.bearing()), String.format(Locale.ROOT, "%.1f", l.totalMetres()),
                    l.eta() == null ? null : l.eta().toString()});
        }
        return ok(request, Ids.FID_PLAN, Forecast.render(legs, basis), new TableResult("?plan forecast " + name,
                List.of("n", "lat", "lon", "leg_m", "bearing", "total_m", "eta"),
                List.of("INTEGER", "DOUBLE", "DOUBLE", "DOUBLE", "DOUBLE", "DOUBLE", "VARCHAR"), rows, false));
    }

    /** The file: in the upload store, else the vehicle's latest download of that name. */
    private record Found(String where, Path path) {}

    private Found find(String mailbox, String name) throws NoSuchFileException {
        FileNames.check(name);
        Path up = host.files().uploadDir().resolve(name);
        if (Files.isRegularFile(up)) {
            return new Found("the upload store", up);
        }
        String folder = FileStore.folderFor(mailbox);
        Path down = host.files().downloadDir().resolve(folder).resolve(name);
        if (Files.isRegularFile(down)) {
            return new Found("the vehicle's downloads (" + folder + "/" + name + ")", down);
        }
        throw new NoSuchFileException("no file '" + name + "' in the upload store nor among " + folder
                + "'s downloads; upload it (put FILE) or fetch it from the vehicle first");
    }

    private PlanCheck read(Found f, String name) throws IOException {
        try (InputStream in = Files.newInputStream(f.path())) {
            return BehaviorFileReader.check(name, in, limits);
        }
    }

    private OutgoingServerMessage check(IncomingServerMessage request, String mailbox, String name) throws IOException {
        Found f = find(mailbox, name);
        PlanCheck c = read(f, name);
        if (!c.ok()) {
            return error(request, Ids.FID_PLAN, ErrorCode.BAD_REQUEST, refusal(c, f));
        }
        return ok(request, Ids.FID_PLAN, "from " + f.where() + "\n" + PlanTable.render(c.file()), table(c.file()));
    }

    private static String refusal(PlanCheck c, Found f) {
        return c.problemText() + "\n" + c.problems().get(0).file() + " (" + f.where() + "): refused, " + c.problems().size()
                + " problem(s)";
    }

    /** The waypoints as a table (n, lat, lon, comment), b_args as rows after them (n empty, lat the b_arg, lon its value). */
    static TableResult table(BehaviorFile f) {
        List<String[]> rows = new ArrayList<>();
        for (Waypoint wp : f.waypoints()) {
            rows.add(new String[] {Integer.toString(wp.n()), String.format(Locale.ROOT, "%.5f", wp.lat()),
                    String.format(Locale.ROOT, "%.5f", wp.lon()), wp.comment()});
        }
        return new TableResult("?plan check " + f.name(), List.of("n", "lat", "lon", "comment"),
                List.of("INTEGER", "DOUBLE", "DOUBLE", "VARCHAR"), rows, false);
    }

    private OutgoingServerMessage send(IncomingServerMessage request, String mailbox, String name, String as) throws IOException {
        String user = request.header().origin().user();
        PermitFile.User u = permitted(request);
        vehicleName(as);
        String folder = FileStore.folderFor(mailbox);
        PermitFile.Decision d = host.permits().decide(u, SERVER, "", "?to-vehicle " + folder);
        if (!d.allowed()) {
            throw new Refused("user '" + user + "' may not put files for a vehicle in to-vehicle/" + folder + " (" + d.because()
                    + "); that takes the right '?to-vehicle " + folder + "' for RIPVServer");
        }
        if (!host.files().isMailboxFolder(folder)) {
            throw new IllegalArgumentException("no vehicle MailBox " + mailbox + " has been seen (its folder " + folder
                    + " is not there); ?mailboxes lists them");
        }
        Found f = find(mailbox, name);
        byte[] bytes;
        try (InputStream in = Files.newInputStream(f.path())) {
            bytes = in.readNBytes(limits.maxBytes() + 1);
        }
        PlanCheck c = BehaviorFileReader.check(name, bytes, limits);
        if (!c.ok()) {
            return error(request, Ids.FID_PLAN, ErrorCode.BAD_REQUEST, refusal(c, f) + "; nothing was staged");
        }
        String staged = ToVehicleFolder.DIR + "/" + folder + "/" + as;
        if (Files.exists(host.files().uploadPath(staged))) {
            throw new FileExistsException(as + " waits to go to " + mailbox + " already (" + staged
                    + ", ?changes " + mailbox + "); nothing was staged: ?delete " + staged + " first to send another in its place");
        }
        long id = book.nextId();
        // staged as its owner, so the to-vehicle round sends it with their rights (docs/serial.md)
        host.files().uploadChunk("plan-" + id, user, staged, 0, bytes.length, bytes, UploadMode.REFUSE, host.permits().quota(u));
        BehaviorFile file = c.file();
        List<double[]> wpts = file.waypoints().stream().map(wp -> new double[] {wp.lat(), wp.lon()}).toList();
        long now = System.currentTimeMillis();
        Change change = new Change(id, mailbox, Change.Kind.FILE, as, "", name, file.sha256(), bytes.length, user,
                Change.State.QUEUED, now, 0, 0, 0, 0, staged, 0, "staged as " + staged + "; it goes on the next call", wpts);
        book.put(change);
        event(change, "queued: staged as " + staged + ", sha256 " + file.sha256());
        versions.sent(mailbox, file.sha256(), sentAs(change));
        return ok(request, Ids.FID_PLAN, "change " + id + ": " + PlanTable.summary(file) + "\nchecked and staged as " + staged
                + ": it goes to " + mailbox + " on its next call (the link's to-vehicle= protocol), with a receipt in "
                + ToVehicleFolder.DIR + "/" + folder + "/" + ToVehicleFolder.SENT + "/" + as + ".receipt; ?changes " + mailbox
                + " follows it", table(file));
    }

    private OutgoingServerMessage set(IncomingServerMessage request, String mailbox, String name, String value) throws IOException {
        String user = request.header().origin().user();
        permitted(request);
        String sensor = name.toLowerCase(Locale.ROOT);
        if (!SENSOR.matcher(sensor).matches()) {
            throw new IllegalArgumentException("'" + name + "' is not a sensor name: letters, digits and '_', starting with a letter,"
                    + " at most 40 (e.g. c_dive_target_depth)");
        }
        if (!NUMBER.matcher(value).matches()) {
            throw new IllegalArgumentException("'" + value + "' is not a number for " + sensor);
        }
        String command = "put " + sensor + " " + value;
        String label = "plan-set-" + sensor + ".wf";
        String source = "workflow once\n# written by ?plan set for " + user + " (docs/plans.md)\nsend \"" + command
                + "\" fail='(?i)unknown|not a |usage|error' timeout=60s\n";
        long workflow;
        try {
            workflow = host.queueWorkflow(mailbox, user, label, source);
        } catch (SecurityException e) {
            throw new Refused(e.getMessage());
        }
        long id = book.nextId();
        long now = System.currentTimeMillis();
        Change change = new Change(id, mailbox, Change.Kind.SET, sensor, value, command, "", 0, user, Change.State.QUEUED, now, 0,
                0, 0, 0, "workflow " + workflow, workflow, "workflow " + workflow + " sends it on the next call", List.of());
        book.put(change);
        event(change, "queued as workflow " + workflow);
        return ok(request, Ids.FID_PLAN, "change " + id + ": '" + command + "' queued for " + mailbox + " as workflow " + workflow
                + " (?queue " + mailbox + "); it runs on the next call, with a receipt (?receipts " + mailbox + "); ?changes "
                + mailbox + " follows it", null);
    }

    OutgoingServerMessage changes(IncomingServerMessage request) {
        String[] w = request.header().body().trim().split("\\s+");
        String user = request.header().origin().user();
        List<Change> list;
        String title;
        if (w.length == 2) {
            String mailbox = address(w[1]);
            mayRead(user, mailbox);
            list = book.of(mailbox);
            title = list.size() + " change(s) for " + mailbox;
        } else if (w.length == 1) {
            // the fleet: every vehicle this user may read, changes not settled yet
            list = book.list(c -> !c.state().settled() && Rights.mayRead(host.permits(), user, c.mailbox()));
            title = list.size() + " pending change(s) on the vehicles you may read";
        } else {
            throw new IllegalArgumentException("usage: ?changes [MAILBOX]");
        }
        StringBuilder b = new StringBuilder(title);
        List<String[]> rows = new ArrayList<>();
        for (Change c : list) {
            long since = Math.max(Math.max(c.queuedAt(), c.sentAt()), Math.max(c.receivedAt(), c.settledAt()));
            String[] row = {Long.toString(c.id()), c.mailbox(), c.what(), c.state().word(), Instant.ofEpochMilli(since).toString(),
                    c.user(), c.sha256(), c.detail(), Instant.ofEpochMilli(c.queuedAt()).toString()};
            rows.add(row);
            b.append(String.format(Locale.ROOT, "%n%4d  %-14s %s  [%s since %s, by %s]%n      %s", c.id(), c.state().word(), c.what(),
                    w.length == 1 ? c.mailbox() : "", row[4], c.user(), c.detail()).replace("[ since", "[since"));
        }
        return ok(request, Ids.FID_CHANGES, b.toString(), new TableResult("?changes", List.of("id", "mailbox", "change", "state",
                "since", "user", "sha256", "detail", "queued"), List.of("INTEGER", "VARCHAR", "VARCHAR", "VARCHAR", "VARCHAR",
                "VARCHAR", "VARCHAR", "VARCHAR", "VARCHAR"), rows, false));
    }

    private void event(Change c, String text) {
        host.publish(ConsoleEntry.event(c.mailbox(), VehicleEvent.PLAN_CHANGE, "change " + c.id() + " " + c.what() + ": " + text,
                null, null));
    }

    private void mayRead(String user, String mailbox) {
        String why = Rights.whyNotRead(host.permits(), user, mailbox);
        if (why != null) {
            throw new Refused(why);
        }
    }

    private PermitFile.User permitted(IncomingServerMessage request) {
        String user = request.header().origin().user();
        PermitFile p = host.permits();
        PermitFile.User u = p.user(user).orElseThrow(() -> new Refused("user '" + user + "' is no longer in the permit file"));
        PermitFile.Decision d = p.decide(u, SERVER, "", request.header().body().trim());
        if (!d.allowed()) {
            throw new Refused("user '" + user + "' may not change a vehicle's plan (" + d.because() + ")");
        }
        return u;
    }

    private static String address(String text) {
        try {
            return MailboxAddress.parse(text).toString();
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("'" + text + "' is not a MailBox address (" + e.getMessage() + "); ?mailboxes lists them");
        }
    }

    private static void need(boolean ok, String usage) {
        if (!ok) {
            throw new IllegalArgumentException(usage);
        }
    }

    static OutgoingServerMessage ok(IncomingServerMessage request, String fid, String text, Result result) {
        return request.reply(Footer.ok(fid, text, result).via(SERVER));
    }

    static OutgoingServerMessage error(IncomingServerMessage request, String fid, ErrorCode code, String text) {
        return request.reply(Footer.error(fid, code, text).via(SERVER));
    }
}
