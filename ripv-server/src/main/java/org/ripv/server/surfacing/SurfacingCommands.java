package org.ripv.server.surfacing;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
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
 * {@code ?surfacings MAILBOX [--last N] [--json]}: a vehicle's call records, oldest first, as a
 * table (the named columns, then every other surface sensor by name) or, with {@code --json}, one
 * JSON object per record by those names. Needs the read right, as {@code ?history} does.
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
        String text;
        if (asJson) {
            try {
                text = json.writeValueAsString(records);
            } catch (JsonProcessingException e) {
                return error(request, fid, ErrorCode.INTERNAL, "call records could not be written as JSON: " + e.getMessage());
            }
        } else {
            text = records.size() + " call record" + (records.size() == 1 ? "" : "s") + " of " + mailbox + ", oldest first"
                    + (records.isEmpty() ? " (no surface dialog read from it yet)" : "\n" + render(columns, rows));
        }
        return request.reply(Footer.ok(fid, text, table).via(via));
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
