package org.ripv.messages;

import java.util.AbstractList;
import java.util.ArrayList;
import java.util.List;
import java.util.RandomAccess;

/**
 * A query's table as it travels: in pages (issue 38). A PROGRESS reply whose result is a
 * {@link TableResult} carries the next rows of the answer; the final OK reply's table carries the
 * rows after the last page and whether the whole was cut ({@code truncated}). Nothing on the way —
 * service, RMI, server — ever holds more than a few pages, so their memory is bounded by the page,
 * not by the result; whoever wants the whole table (the CLI, the Swing client, the web page, the
 * server's own {@code vis:} calls) joins the pages with this class and sees one table as before.
 *
 * <p>The reader's side is bounded too: past {@code maxRows} the rows are dropped and the joined
 * table is marked truncated, so a peer that sends pages without end cannot exhaust the reader.
 */
public final class TablePages {
    /** Rows a reader keeps by default: far above any service's {@code --max-rows}. */
    public static final int DEFAULT_MAX_ROWS = 5_000_000;

    private final int maxRows;
    private List<String[]> rows = new ArrayList<>();
    private boolean cut;
    /** The pages' common width, -1 before the first, -2 once two differed. */
    private int width = -1;

    public TablePages() {
        this(DEFAULT_MAX_ROWS);
    }

    public TablePages(int maxRows) {
        this.maxRows = maxRows;
    }

    /** True for a reply that is one page of a table: PROGRESS with a {@link TableResult}. */
    public static boolean isPage(Footer f) {
        return f.status() == Status.PROGRESS && f.result() instanceof TableResult;
    }

    /** Keeps a page's rows, in the order the pages came. */
    public synchronized void add(TableResult page) {
        take(page);
    }

    /** How many rows the pages so far held. */
    public synchronized int rows() {
        return rows.size();
    }

    /** The whole table: the pages' rows, then {@code last}'s, with {@code last}'s columns and truncation. */
    public synchronized TableResult join(TableResult last) {
        if (rows.isEmpty()) {
            return last;
        }
        take(last);
        // Each page's rows were checked against its columns when it was built: when every page had
        // as many columns as the last, the joined rows need no second look (nor a second copy).
        List<String[]> all = width == last.columns().size() ? new CheckedRows(rows, width) : rows;
        rows = new ArrayList<>(); // handed over: nothing here changes them any more
        return new TableResult(last.query(), last.columns(), last.types(), all, last.truncated() || cut);
    }

    /** The final reply with the pages' rows put in front of its own; any other reply as it is. */
    public Footer join(Footer last) {
        return last.result() instanceof TableResult t ? last.withResult(join(t)) : last;
    }

    private void take(TableResult page) {
        int w = page.columns().size();
        width = width == -1 || width == w ? w : -2;
        for (String[] row : page.rows()) {
            if (rows.size() == maxRows) {
                cut = true;
                return;
            }
            rows.add(row);
        }
    }

    /** Rows of one width, each checked by the TableResult it came in; read-only. */
    static final class CheckedRows extends AbstractList<String[]> implements RandomAccess {
        private final List<String[]> rows;
        private final int width;

        private CheckedRows(List<String[]> rows, int width) {
            this.rows = rows;
            this.width = width;
        }

        int width() {
            return width;
        }

        @Override
        public String[] get(int index) {
            return rows.get(index);
        }

        @Override
        public int size() {
            return rows.size();
        }
    }
}
