package org.ripv.server.dataloop;

import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.function.Supplier;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;

/**
 * Plots from data, orchestrated by the server: {@code vis:sql SELECT ...}, {@code vis:track
 * VEHICLE [since=ISO-TIME]}, {@code vis:depth VEHICLE [since=]} and {@code vis:profile VEHICLE SENSOR
 * [since=]} addressed to a DataVisServer MailBox. The server runs the query on a DatabaseServer
 * MailBox as the user (with the user's roles, and only if the permit file lets the user send it
 * there), turns the table into the data file of docs/datavis.md, and sends that to the DataVisServer
 * as an ordinary {@code vis:NAME} with the file attached: the thesis's data.dat/info.dat exchange is
 * unchanged for the workers. The JPEG comes back to the user and lands in the download directory.
 */
final class PlotRequests {
    private static final Pattern VEHICLE = Pattern.compile("[A-Za-z0-9_.\\-]{1,64}");
    private static final Pattern SENSOR = Pattern.compile("[A-Za-z0-9_]{1,64}");
    private static final Pattern OUT = Pattern.compile("[A-Za-z0-9_\\-]{1,100}");
    private static final DateTimeFormatter SQL_TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss");

    private final ServiceCalls calls;
    private final Supplier<String> defaultDatabase;

    PlotRequests(ServiceCalls calls, Supplier<String> defaultDatabase) {
        this.calls = calls;
        this.defaultDatabase = defaultDatabase;
    }

    /** A parsed plot request. */
    record Plan(String kind, String sql, String output, List<String> labels, String vehicle, String database, String since) {
        Plan(String kind, String sql, String output, List<String> labels, String vehicle, String database) {
            this(kind, sql, output, labels, vehicle, database, null);
        }
    }

    boolean handle(IncomingServerMessage request, String visMailbox, Consumer<OutgoingServerMessage> send) {
        Plan plan;
        try {
            plan = parse(request.header().body().strip());
        } catch (IllegalArgumentException e) {
            send.accept(error(request, ErrorCode.BAD_REQUEST, e.getMessage()));
            return true;
        }
        String user = request.header().origin().user();
        if (plan.database() == null) {
            send.accept(error(request, ErrorCode.UNKNOWN_SERVICE, "no DatabaseServer is registered to query for "
                    + plan.kind()));
            return true;
        }
        if (!calls.permitted(user, plan.database(), plan.sql())) {
            send.accept(error(request, ErrorCode.FORBIDDEN, "user '" + user + "' may not query " + plan.database()
                    + " for " + plan.kind()));
            return true;
        }
        send.accept(progress(request, "querying " + plan.database() + " for " + plan.kind()));
        query(request, plan, plan.sql(), send, t -> {
            if (!plan.kind().equals("track") || t.rows().isEmpty()) {
                plot(request, visMailbox, plan, t, null, send);
                return;
            }
            // the newest fix, then every fix up to it: the mark and the points agree even while an ingest runs
            String[] newest = t.rows().get(0);
            String points = trackPointsSql(plan.vehicle(), plan.since(), newest[0]);
            if (!calls.permitted(user, plan.database(), points)) {
                send.accept(error(request, ErrorCode.FORBIDDEN, "user '" + user + "' may not query " + plan.database()
                        + " for " + plan.kind()));
                return;
            }
            query(request, plan, points, send, p -> plot(request, visMailbox, plan, p,
                    "newest fix " + newest[0] + " UTC (" + newest[1] + ")", send));
        });
        return true;
    }

    /** Runs one query as the user; hands its table on, or answers the error. */
    private void query(IncomingServerMessage request, Plan plan, String sql, Consumer<OutgoingServerMessage> send,
                       Consumer<TableResult> then) {
        String user = request.header().origin().user();
        calls.call(plan.database(), sql, user, request.header().roles(), null, f -> { }).whenComplete((f, e) -> {
            try {
                if (e != null) {
                    send.accept(error(request, ErrorCode.INTERNAL, "the query failed: " + e));
                } else if (f.status() == Status.ERROR && !plan.kind().equals("sql") && noSchemaYet(f.replyText())) {
                    send.accept(error(request, ErrorCode.BAD_REQUEST, noDataYet(plan)));
                } else if (f.status() != Status.OK || !(f.result() instanceof TableResult t)) {
                    send.accept(error(request, f.status() == Status.ERROR ? f.errorCode() : ErrorCode.BAD_REQUEST,
                            "the query for " + plan.kind() + " failed: " + (f.status() == Status.OK
                                    ? "it is not a SELECT (no table came back)" : f.replyText())));
                } else {
                    then.accept(t);
                }
            } catch (RuntimeException x) {
                send.accept(error(request, ErrorCode.BAD_REQUEST, x.getMessage()));
            }
        });
    }

    private void plot(IncomingServerMessage request, String visMailbox, Plan plan, TableResult t, String mark,
                      Consumer<OutgoingServerMessage> send) {
        if (t.rows().isEmpty()) {
            send.accept(error(request, ErrorCode.BAD_REQUEST, switch (plan.kind()) {
                case "sql" -> "the query returned no rows: nothing to plot";
                case "profile" -> "no readings of that sensor with depths for vehicle '" + plan.vehicle() + "' in " + plan.database()
                        + " (SELECT DISTINCT name FROM sensor_def lists the sensors; " + NO_DATA_HELP + ")";
                default -> noDataYet(plan);
            }));
            return;
        }
        if (t.columns().size() < 2) {
            send.accept(error(request, ErrorCode.BAD_REQUEST, "vis:sql plots the first column against the others: select"
                    + " at least two columns"));
            return;
        }
        List<String> labels = new ArrayList<>(plan.labels());
        List<String[]> cells = new ArrayList<>(t.rows());
        List<String> types = t.types();
        String note = t.truncated() ? " (the query was cut at the DatabaseServer's row limit: "
                + (plan.kind().equals("sql") ? "the first " : "the newest ") + cells.size() + " rows are plotted)" : "";
        List<String[]> rows;
        if (plan.kind().equals("sql")) {
            rows = TableData.tokens(t);
            labels.add("xlabel: " + t.columns().get(0));
            labels.add("legend: " + String.join(" | ", t.columns().subList(1, t.columns().size())));
            if (TableData.isTime(types.get(0))) {
                labels.add("plot: time");
            }
        } else {
            // newest first from the query (so a cut keeps the newest); drawn oldest to newest
            Collections.reverse(cells);
            rows = new ArrayList<>(cells.size());
            for (String[] c : cells) {
                rows.add(new String[] {TableData.token(c[0], types.get(0), t.columns().get(0)),
                        TableData.token(c[1], types.get(1), t.columns().get(1))});
            }
            if (mark != null) {
                labels.add("mark: " + mark);
            }
        }
        byte[] data = TableData.write(labels, rows);
        String file = plan.output() + ".dat";
        send.accept(progress(request, "plotting " + rows.size() + " rows from " + plan.database()));
        calls.call(visMailbox, "vis:" + file + " out=" + plan.output(), request.header().origin().user(),
                request.header().roles(), new Attachment(file, data), p -> { }).whenComplete((f, e) -> {
                    if (e != null) {
                        send.accept(error(request, ErrorCode.INTERNAL, "the plot failed: " + e));
                    } else {
                        send.accept(request.reply(f.withText(f.replyText() + note)));
                    }
                });
    }

    /** What to do when a vehicle has no Slocum data: the same words before the first ingest and after others'. */
    private static final String NO_DATA_HELP = "fetch its data files (DBA, or binary .sbd .tbd .scd .tcd with their .cac) with ymodem:get NAME... on its SerialPortServer MailBox"
            + " (they are ingested automatically) or ingest NAME... on the DatabaseServer for files already downloaded;"
            + " SELECT DISTINCT vehicle FROM data_file lists the vehicles that have data";

    private static String noDataYet(Plan plan) {
        return "no Slocum data for '" + plan.vehicle() + "' yet in " + plan.database() + ": " + NO_DATA_HELP;
    }

    /**
     * True when the query failed because the Slocum tables are not there: they are made by the
     * first ingest (Derby's SQLState 42X05, PostgreSQL's 42P01: no such table or view).
     */
    static boolean noSchemaYet(String replyText) {
        return replyText.contains("SQLState 42X05") || replyText.contains("SQLState 42P01");
    }

    /** The plot commands, for a {@code vis:} word that is neither one of them nor an uploaded file. */
    static final List<String> COMMANDS = Stream.concat(Stream.of(PlotKind.values()).map(k -> k.usage),
            Stream.of("vis:file NAME x=COLUMN y=COLUMN", "vis:NAME (a data file in the upload directory)")).toList();

    /**
     * The error for {@code vis:WORD} when there is no uploaded file WORD: a typo of a plot command
     * is the likelier mistake, so the plot commands come first (and the nearest, if one is near).
     */
    static String notAPlot(String word, String noFile) {
        String near = null;
        for (String k : Stream.concat(Stream.of(PlotKind.values()).map(p -> p.word), Stream.of("file")).toList()) {
            if (Typos.near(word.toLowerCase(Locale.ROOT), k)) {
                near = k;
            }
        }
        return "'vis:" + word + "' is not a plot command" + (near == null ? "" : " (did you mean vis:" + near + "?)")
                + " and " + noFile.replaceFirst("^no file", "there is no file") + "; the plot commands are: " + String.join(", ", COMMANDS);
    }

    Plan parse(String body) {
        PlotKind plot = PlotKind.of(body).orElseThrow(() -> new IllegalArgumentException("unknown plot " + body.strip()
                .split("\\s+", 2)[0] + "; the plot commands are: " + String.join(", ", COMMANDS)));
        String kind = plot.word;
        String rest = body.strip().substring("vis:".length());
        String args = rest.substring(kind.length()).strip();
        if (plot == PlotKind.SQL) {
            if (args.isEmpty()) {
                throw new IllegalArgumentException("usage: vis:sql SELECT x, y1 [, y2 ...] FROM ... (the first column"
                        + " against the others)");
            }
            String title = args.length() <= 80 ? args : args.substring(0, 77) + "...";
            return new Plan("sql", args, "sql-plot", List.of("title: " + title), null, defaultDatabase.get());
        }
        List<String> words = new ArrayList<>();
        String since = null;
        String db = null;
        String out = null;
        for (String w : args.isEmpty() ? new String[0] : args.split("\\s+")) {
            int eq = w.indexOf('=');
            if (eq > 0) {
                String key = w.substring(0, eq).toLowerCase(Locale.ROOT);
                String value = w.substring(eq + 1);
                switch (key) {
                    case "since" -> since = sqlTime(value);
                    case "db" -> db = value;
                    case "out" -> {
                        if (!OUT.matcher(value).matches()) {
                            throw new IllegalArgumentException("out='" + value + "': use letters, digits, '_' and '-'");
                        }
                        out = value;
                    }
                    default -> throw new IllegalArgumentException("unknown option '" + key + "' of vis:" + kind
                            + "; options are since=ISO-TIME, db=MAILBOX, out=NAME");
                }
            } else {
                words.add(w);
            }
        }
        int wanted = plot.words;
        if (words.size() != wanted) {
            throw new IllegalArgumentException("usage: vis:" + kind + " VEHICLE" + (wanted == 2 ? " SENSOR" : "")
                    + " [since=2016-01-13T00:00:00Z] [db=MAILBOX] [out=NAME]");
        }
        String vehicle = words.get(0);
        if (!VEHICLE.matcher(vehicle).matches()) {
            throw new IllegalArgumentException("'" + vehicle + "' is not a vehicle name (letters, digits, '_', '-', '.')");
        }
        String database = db != null ? db : defaultDatabase.get();
        String when = since == null ? "" : " AND time_utc >= CAST('" + since + "' AS TIMESTAMP)";
        return switch (plot) {
            case TRACK -> new Plan(kind, newestFixSql(vehicle, since), out != null ? out : "track-" + vehicle,
                    List.of("title: track of " + vehicle + (since == null ? "" : " since " + since + " UTC"),
                            "xlabel: longitude (degrees east)", "ylabel: latitude (degrees north)", "legend: positions",
                            "plot: track", "size: 800x800"), vehicle, database, since);
            case DEPTH -> new Plan(kind, "SELECT time_utc, depth FROM depths WHERE vehicle = '" + vehicle + "'"
                    + " AND source = 'm_depth'" + when + " ORDER BY time_utc DESC", out != null ? out : "depth-" + vehicle,
                    List.of("title: depth of " + vehicle, "xlabel: time (UTC)", "ylabel: depth (m)", "legend: m_depth",
                            "plot: depth"), vehicle, database);
            case PROFILE -> {
                String sensor = words.get(1);
                if (!SENSOR.matcher(sensor).matches()) {
                    throw new IllegalArgumentException("'" + sensor + "' is not a sensor name");
                }
                String w = since == null ? "" : " AND r.t >= CAST('" + since + "' AS TIMESTAMP)";
                yield new Plan(kind, "SELECT r.value, d.depth FROM sensor_def s JOIN reading r ON r.sensor_id = s.sensor_id"
                        + " JOIN depths d ON d.file_id = r.file_id AND d.row_no = r.row_no WHERE s.name = '" + sensor
                        + "' AND r.vehicle = '" + vehicle + "'" + w + " ORDER BY r.t DESC",
                        out != null ? out : "profile-" + vehicle + "-" + sensor,
                        List.of("title: " + sensor + " of " + vehicle + " against depth", "xlabel: " + sensor,
                                "ylabel: depth (m)", "legend: " + sensor, "plot: profile"), vehicle, database);
            }
            case SQL -> throw new IllegalStateException("vis:sql is planned above");
        };
    }

    /** A track's first query: the vehicle's newest fix (its time and source), for the mark. */
    static String newestFixSql(String vehicle, String since) {
        return "SELECT time_utc, source FROM positions WHERE vehicle = '" + vehicle + "'" + sinceSql(since)
                + " ORDER BY time_utc DESC FETCH FIRST 1 ROWS ONLY";
    }

    /**
     * A track's points up to its newest fix, newest first, longitude and latitude only (100,000 of
     * them are 200,000 numbers to carry, not 400,000 cells): on the positions view, which reads
     * POSITION_FIX, one range of its (vehicle, t DESC, lat, lon, source, file_id) index with no join
     * and no sort (docs/database.md).
     */
    static String trackPointsSql(String vehicle, String since, String newest) {
        if (!newest.matches("[0-9][0-9 :.\\-]{9,40}")) {
            throw new IllegalArgumentException("the database's newest fix time '" + newest + "' is not a time");
        }
        return "SELECT lon, lat FROM positions WHERE vehicle = '" + vehicle + "'" + sinceSql(since)
                + " AND time_utc <= CAST('" + newest + "' AS TIMESTAMP) ORDER BY time_utc DESC";
    }

    private static String sinceSql(String since) {
        return since == null ? "" : " AND time_utc >= CAST('" + since + "' AS TIMESTAMP)";
    }

    /** An ISO time (2016-01-13T17:00:00Z, 2016-01-13T17:00, 2016-01-13) as SQL's UTC timestamp text. */
    static String sqlTime(String iso) {
        try {
            LocalDateTime t;
            if (iso.endsWith("Z") || iso.matches(".*[+-]\\d\\d:\\d\\d$")) {
                t = LocalDateTime.ofInstant(Instant.from(DateTimeFormatter.ISO_OFFSET_DATE_TIME.parse(iso)), ZoneOffset.UTC);
            } else if (iso.length() == 10) {
                t = LocalDate.parse(iso).atStartOfDay();
            } else {
                t = LocalDateTime.parse(iso);
            }
            return t.format(SQL_TIME);
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException("since='" + iso + "' is not an ISO time such as 2016-01-13T17:00:00Z");
        }
    }

    private static OutgoingServerMessage error(IncomingServerMessage request, ErrorCode code, String text) {
        return request.reply(Footer.error(Ids.SID_DATAVIS, code, text).via("RIPVServer"));
    }

    private static OutgoingServerMessage progress(IncomingServerMessage request, String text) {
        return request.reply(Footer.progress(Ids.SID_DATAVIS, text, null).via("RIPVServer"));
    }
}
