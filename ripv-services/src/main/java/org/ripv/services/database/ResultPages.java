package org.ripv.services.database;

import java.sql.ResultSet;
import java.sql.ResultSetMetaData;
import java.sql.SQLException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.ripv.messages.PackedRows;
import org.ripv.messages.TableResult;
import org.ripv.service.Request;

/**
 * How a query's rows leave the service (issue 38): in pages, the first small so the first rows
 * reach the operator at once, each next one twice as large up to {@link #MAX_PAGE_CHARS}, each
 * sent only once the reader has taken all but one of those before it ({@link Request#page}). The
 * service thus holds one page being filled, and the way to the reader at most two more, whatever
 * the size of the result; the database's cursor waits meanwhile, and a cancel closes it.
 *
 * <p>Without a request (the in-process {@link DatabaseHandler#run(String, boolean)}) nothing is
 * paged: the whole table comes in the final reply, as before.
 *
 * <p>Runs on the MailBox's thread, one query at a time.
 */
final class ResultPages {
    /** The first page: what the operator sees at once. */
    static final int FIRST_PAGE_ROWS = 100;
    /** The largest page, in characters of its cells plus {@link #CELL_OVERHEAD} per cell. */
    static final long MAX_PAGE_CHARS = 512 * 1024;
    /** What a cell costs on the heap besides its characters (its String and the row's slot), as characters. */
    static final int CELL_OVERHEAD = 12;
    /** How long a reader may take no page before the query is stopped (a client that left, or hangs). */
    static final Duration READER_WAIT = Duration.ofSeconds(60);
    /** Longest text kept of one cell; the rest is cut with a note. */
    static final int MAX_CELL_CHARS = 10_000;

    private final Request request;
    private final QueryLimits limits;
    private final RunningStatement running;
    private int maxRows = FIRST_PAGE_ROWS;
    private long maxChars = MAX_PAGE_CHARS / 32;
    private int sent;
    private int pages;

    /** @param running told when the rows wait for their reader (that time is not the database's) */
    ResultPages(Request request, QueryLimits limits, RunningStatement running) {
        this.request = request;
        this.limits = limits;
        this.running = running;
    }

    /**
     * Reads the rows into pages: each full page goes to the reader and the rows after the last
     * page are the returned table, so the service holds one page at a time (and the reader up to
     * {@code Request.PAGES_IN_FLIGHT} more), never the whole result. Cut at
     * {@link QueryLimits#maxRows()} or at the result's size limit (then marked truncated).
     */
    TableResult read(String sql, ResultSet rs) throws SQLException, Request.PagesStopped, InterruptedException {
        ResultSetMetaData md = rs.getMetaData();
        int n = md.getColumnCount();
        List<String> columns = new ArrayList<>(n);
        List<String> types = new ArrayList<>(n);
        for (int i = 1; i <= n; i++) {
            columns.add(md.getColumnLabel(i));
            types.add(md.getColumnTypeName(i));
        }
        // Packed as read (PackedRows): a page is one byte array from here to whoever reads it, no
        // String[] per row, nothing packed again on the way (docs/performance.md, "The database").
        PackedRows.Builder rows = PackedRows.builder(n);
        String[] row = new String[n];
        long chars = 0;
        long pageChars = 0;
        int kept = 0;
        boolean truncated = false;
        while (rs.next()) {
            if (kept == limits.maxRows()) {
                truncated = true;
                break;
            }
            long rowChars = 0;
            for (int i = 0; i < n; i++) {
                String v = cell(rs, i + 1);
                row[i] = v;
                rowChars += v == null ? 1 : v.length() + 1;
            }
            chars += rowChars;
            if (chars > limits.maxResultChars()) {
                truncated = true;
                break;
            }
            rowChars += (long) CELL_OVERHEAD * n;
            if (full(rows.rows(), pageChars + rowChars)) {
                send(new TableResult(sql, columns, types, rows.build(), false));
                pageChars = 0;
            }
            for (String v : row) {
                rows.cell(v);
            }
            rows.endRow();
            pageChars += rowChars;
            kept++;
        }
        return new TableResult(sql, columns, types, rows.build(), truncated);
    }

    private static String cell(ResultSet rs, int column) throws SQLException {
        String v;
        try {
            v = rs.getString(column);
        } catch (SQLException e) {
            // e.g. a BLOB: show what it is rather than fail the whole query
            Object o = rs.getObject(column);
            v = o == null ? null : "<" + o.getClass().getSimpleName() + ">";
        }
        if (v != null && v.length() > MAX_CELL_CHARS) {
            v = v.substring(0, MAX_CELL_CHARS) + "... (" + v.length() + " characters)";
        }
        return v;
    }

    /** Whether a page of {@code rows} rows weighing {@code chars} is full, so that it goes before the next row. */
    private boolean full(int rows, long chars) {
        return request != null && rows > 0 && (rows >= maxRows || chars >= maxChars);
    }

    /** Sends a full page once the reader has room for it; the next page may be twice as large. */
    private void send(TableResult page) throws Request.PagesStopped, InterruptedException {
        int first = sent + 1;
        sent += page.rows().size();
        pages++;
        running.pause();
        try {
            request.page("rows " + first + "-" + sent, page, READER_WAIT);
        } finally {
            running.resume();
        }
        maxRows = maxRows >= Integer.MAX_VALUE / 2 ? Integer.MAX_VALUE : maxRows * 2;
        maxChars = Math.min(MAX_PAGE_CHARS, maxChars * 2);
    }

    /** Rows sent in pages so far (the final reply carries the rest). */
    int sent() {
        return sent;
    }

    /** Pages sent so far. */
    int pages() {
        return pages;
    }
}
