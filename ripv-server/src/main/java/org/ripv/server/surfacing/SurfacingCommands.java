package org.ripv.server.surfacing;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;
import org.ripv.commands.OptionValues;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.TableResult;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.session.Rights;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code ?surfacings MAILBOX [--last N] [--json] [--outlook]}: a vehicle's call records, oldest
 * first, as a table (the named columns, then every other surface sensor by name) or, with
 * {@code --json}, one JSON object per record by those names. {@code --outlook} adds what the
 * records say comes next ({@link org.ripv.surfacing.CallOutlook}: the next call, the waypoint's
 * distance, bearing and ETA, the trends); with {@code --json} the answer is then
 * {@code {"records": […], "outlook": {…}}}. Needs the read right, as {@code ?history} does.
 */
public final class SurfacingCommands {
    static final int DEFAULT_LAST = 20;
    private final Surfacings surfacings;
    private final Supplier<PermitFile> permits;
    private final String via;
    private final ObjectMapper json = new ObjectMapper();

    public SurfacingCommands(Surfacings surfacings, Supplier<PermitFile> permits, String via) {
        this.surfacings = surfacings;
        this.permits = permits;
        this.via = via;
    }

    /** The words of {@code ?surfacings}, read by picocli through the server's command table. */
    public static final class Options {
        @Parameters(index = "0", paramLabel = "MAILBOX")
        String mailbox;
        @Option(names = "--last", paramLabel = "N", converter = OptionValues.Last.class)
        int last = DEFAULT_LAST;
        @Option(names = "--json")
        boolean json;
        @Option(names = "--outlook")
        boolean outlook;
    }

    public OutgoingServerMessage run(IncomingServerMessage request, String fid, Options options) {
        String mailbox;
        try {
            mailbox = MailboxAddress.parse(options.mailbox).toString();
        } catch (IllegalArgumentException e) {
            return error(request, fid, ErrorCode.UNKNOWN_MAILBOX, e.getMessage());
        }
        int last = options.last;
        boolean asJson = options.json;
        boolean outlook = options.outlook;
        String why = Rights.whyNotRead(permits.get(), request.header().origin().user(), mailbox);
        if (why != null) {
            return error(request, fid, ErrorCode.FORBIDDEN, why);
        }
        List<Map<String, Object>> records = surfacings.last(mailbox, last);
        List<String> columns = columns(records);
        List<String[]> rows = new ArrayList<>();
        for (Map<String, Object> r : records) {
            String[] row = new String[columns.size()];
            for (int c = 0; c < row.length; c++) {
                Object v = r.get(columns.get(c));
                row[c] = v == null ? null : String.valueOf(v);
            }
            rows.add(row);
        }
        TableResult table = new TableResult("?surfacings " + mailbox, columns, columns.stream().map(CallRecord::type).toList(),
                rows, false);
        Map<String, Object> ahead = outlook ? surfacings.outlook(mailbox, records) : null;
        String text;
        if (asJson) {
            try {
                text = json.writeValueAsString(outlook ? Map.of("records", records, "outlook", ahead) : records);
            } catch (JsonProcessingException e) {
                return error(request, fid, ErrorCode.INTERNAL, "call records could not be written as JSON: " + e.getMessage());
            }
        } else {
            text = records.size() + " call record" + (records.size() == 1 ? "" : "s") + " of " + mailbox + ", oldest first"
                    + (records.isEmpty() ? " (no surface dialog read from it yet)" : "\n" + render(columns, rows))
                    + (outlook ? "\n" + words(ahead) : "");
        }
        return request.reply(Footer.ok(fid, text, table).via(via));
    }

    /** The outlook for people: the next call, the waypoint and the way made good to it. */
    static String words(Map<String, Object> o) {
        StringBuilder b = new StringBuilder();
        b.append("next call: ").append(o.get("next_call_utc") == null ? "not known (no interval set or learned yet)"
                : o.get("next_call_utc") + " (every " + o.get("interval_s") + " s, " + o.get("interval_from") + ")");
        if (o.get("sog_mps") != null) {
            b.append(String.format(Locale.ROOT, "%nover ground: %.3f m/s toward %.0f°", o.get("sog_mps"), o.get("cog_deg")));
        }
        if (o.get("current_mps") != null) {
            b.append(String.format(Locale.ROOT, "%ndepth-averaged current: %.3f m/s toward %.0f°", o.get("current_mps"),
                    o.get("current_toward_deg")));
        }
        if (o.get("wpt_lat") == null) {
            b.append("\nwaypoint: not shown (no c_wpt_lat/c_wpt_lon)");
        } else {
            b.append(String.format(Locale.ROOT, "%nwaypoint %.5f, %.5f", o.get("wpt_lat"), o.get("wpt_lon")));
            if (o.get("wpt_distance_m") != null) {
                b.append(String.format(Locale.ROOT, ": %.2f km at %.0f° from the last fix", (Double) o.get("wpt_distance_m") / 1000,
                        o.get("wpt_bearing_deg")));
            }
            b.append(o.get("wpt_eta_utc") != null ? ", ETA " + o.get("wpt_eta_utc") + String.format(Locale.ROOT,
                    " (%.3f m/s made good)", o.get("wpt_made_good_mps"))
                    : o.get("wpt_made_good_mps") != null ? ", no ETA: the glider does not make way toward it" : ", no ETA: no speed over ground yet");
        }
        return b.toString();
    }

    /** The named columns, then every other column the records have, in the order first seen. */
    static List<String> columns(List<Map<String, Object>> records) {
        Set<String> all = new LinkedHashSet<>(CallRecord.COLUMNS);
        records.forEach(r -> all.addAll(r.keySet()));
        return List.copyOf(all);
    }

    /** Columns padded to their widths; an empty cell is {@code -}. */
    static String render(List<String> columns, List<String[]> rows) {
        int[] width = new int[columns.size()];
        for (int c = 0; c < width.length; c++) {
            width[c] = columns.get(c).length();
            for (String[] row : rows) {
                width[c] = Math.max(width[c], cell(row[c]).length());
            }
        }
        StringBuilder b = new StringBuilder();
        for (int c = 0; c < width.length; c++) {
            b.append(c == 0 ? "" : "  ").append(pad(columns.get(c), width[c]));
        }
        for (String[] row : rows) {
            b.append('\n');
            for (int c = 0; c < width.length; c++) {
                b.append(c == 0 ? "" : "  ").append(pad(cell(row[c]), width[c]));
            }
        }
        return b.toString();
    }

    private static String cell(String s) {
        if (s == null) {
            return "-";
        }
        String flat = s.replaceAll("\\s+", " ");
        return flat.length() <= 60 ? flat : flat.substring(0, 59) + "…";
    }

    private static String pad(String s, int width) {
        return s + " ".repeat(Math.max(0, width - s.length()));
    }

    private OutgoingServerMessage error(IncomingServerMessage request, String fid, ErrorCode code, String text) {
        return request.reply(Footer.error(fid, code, text).via(via));
    }
}
