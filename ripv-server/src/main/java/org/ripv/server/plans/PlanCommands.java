package org.ripv.server.plans;

import java.io.IOException;
import java.nio.file.Files;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
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
import org.ripv.plans.PlanCheck;
import org.ripv.plans.PlanLimits;
import org.ripv.plans.PlanTable;
import org.ripv.server.files.FileExistsException;
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
 * {@code save} and {@code history} are {@link SavedPlans}'; {@code current} and {@code forecast}
 * {@link PlanForecasts}'; where files come from, {@link PlanFiles}; the rights, {@link PlanRights}.
 */
final class PlanCommands {
    static final String SERVER = "RIPVServer";
    private static final Pattern SENSOR = Pattern.compile("[a-z][a-z0-9_]{0,39}");
    static final Pattern NUMBER = Pattern.compile("[+-]?(\\d{1,15}(\\.\\d{0,15})?|\\.\\d{1,15})([eE][+-]?\\d{1,3})?");

    private final PlanHost host;
    private final ChangeBook book;
    private final PlanLimits limits;
    private final PlanVersions versions;
    private final PlanFiles files;
    private final PlanRights rights;
    private final SavedPlans saved;
    private final PlanForecasts forecasts;

    PlanCommands(PlanHost host, ChangeBook book, PlanLimits limits, Fixes fixes, PlanVersions versions) {
        this.host = host;
        this.book = book;
        this.limits = limits;
        this.versions = versions;
        this.files = new PlanFiles(host, limits);
        this.rights = new PlanRights(host);
        this.saved = new SavedPlans(versions, book, files, rights, limits);
        this.forecasts = new PlanForecasts(book, fixes, files, limits);
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
            rights.mayRead(request.header().origin().user(), mailbox);
            return forecasts.current(request, mailbox);
        }
        if (w.length < 4) {
            throw new IllegalArgumentException(usage);
        }
        String mailbox = address(w[1]);
        String user = request.header().origin().user();
        rights.mayRead(user, mailbox);
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
                yield forecasts.forecast(request, mailbox, w[3], w.length == 5 ? w[4] : null);
            }
            case "save" -> {
                need(w.length == 4 || (w.length == 6 && w[4].equalsIgnoreCase("as")), "usage: ?plan MAILBOX save FILE [as NAME]");
                yield saved.save(request, mailbox, w[3], w.length == 6 ? w[5] : w[3]);
            }
            case "history" -> {
                need(w.length == 4 || w.length == 5, "usage: ?plan MAILBOX history NAME [N]");
                yield saved.history(request, mailbox, w[3], w.length == 5 ? w[4] : null);
            }
            default -> throw new IllegalArgumentException(usage);
        };
    }

    private OutgoingServerMessage check(IncomingServerMessage request, String mailbox, String name) throws IOException {
        PlanFiles.Found f = files.find(mailbox, name);
        PlanCheck c = files.read(f, name);
        if (!c.ok()) {
            return error(request, Ids.FID_PLAN, ErrorCode.BAD_REQUEST, PlanFiles.refusal(c, f));
        }
        return ok(request, Ids.FID_PLAN, "from " + f.where() + "\n" + PlanTable.render(c.file()), PlanFiles.table(c.file()));
    }

    private OutgoingServerMessage send(IncomingServerMessage request, String mailbox, String name, String as) throws IOException {
        String user = request.header().origin().user();
        PermitFile.User u = rights.permitted(request);
        PlanFiles.vehicleName(as);
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
        PlanFiles.Found f = files.find(mailbox, name);
        byte[] bytes = files.readBounded(f);
        PlanCheck c = BehaviorFileReader.check(name, bytes, limits);
        if (!c.ok()) {
            return error(request, Ids.FID_PLAN, ErrorCode.BAD_REQUEST, PlanFiles.refusal(c, f) + "; nothing was staged");
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
        versions.sent(mailbox, file.sha256(), SavedPlans.sentAs(change));
        return ok(request, Ids.FID_PLAN, "change " + id + ": " + PlanTable.summary(file) + "\nchecked and staged as " + staged
                + ": it goes to " + mailbox + " on its next call (the link's to-vehicle= protocol), with a receipt in "
                + ToVehicleFolder.DIR + "/" + folder + "/" + ToVehicleFolder.SENT + "/" + as + ".receipt; ?changes " + mailbox
                + " follows it", PlanFiles.table(file));
    }

    private OutgoingServerMessage set(IncomingServerMessage request, String mailbox, String name, String value) throws IOException {
        String user = request.header().origin().user();
        rights.permitted(request);
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
            rights.mayRead(user, mailbox);
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

    private static String address(String text) {
        try {
            return MailboxAddress.parse(text).toString();
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("'" + text + "' is not a MailBox address (" + e.getMessage() + "); ?mailboxes lists them");
        }
    }

    static void need(boolean ok, String usage) {
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
