package org.ripv.messages;

import java.util.AbstractList;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Iterator;
import java.util.List;
import java.util.NoSuchElementException;
import java.util.Objects;
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
    /**
     * The pages' rows as they came, in order. A page of {@link PackedRows} stays packed until a row
     * of it is read: a reader joining a 100,000-row query holds its 5.6 MiB of bytes, not 500,000
     * Strings, while the rest arrives, and builds the Strings once, when someone reads the rows
     * (docs/performance.md, "The database").
     */
    private List<List<String[]>> pages = new ArrayList<>();
    private int rows;
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
        return rows;
    }

    /** The whole table: the pages' rows, then {@code last}'s, with {@code last}'s columns and truncation. */
    public synchronized TableResult join(TableResult last) {
        if (pages.isEmpty()) {
            return last;
        }
        take(last);
        // Each page's rows were checked against its columns when it was built: when every page had
        // as many columns as the last, the joined rows need no second look (nor a copy, nor a decoding).
        List<String[]> all;
        if (width == last.columns().size()) {
            all = new CheckedRows(pages, rows, width);
        } else {
            all = new ArrayList<>(rows);
            for (List<String[]> page : pages) {
                all.addAll(page);
            }
        }
        pages = new ArrayList<>(); // handed over: nothing here changes them any more
        rows = 0;
        return new TableResult(last.query(), last.columns(), last.types(), all, last.truncated() || cut);
    }

    /** The final reply with the pages' rows put in front of its own; any other reply as it is. */
    public Footer join(Footer last) {
        return last.result() instanceof TableResult t ? last.withResult(join(t)) : last;
    }

    private void take(TableResult page) {
        int w = page.columns().size();
        width = width == -1 || width == w ? w : -2;
        List<String[]> r = page.rows();
        int room = maxRows - rows;
        if (r.size() > room) {
            cut = true;
            r = r.subList(0, room);
        }
        if (!r.isEmpty()) {
            pages.add(r);
            rows += r.size();
        }
    }

    /**
     * Rows of one width, each checked by the TableResult it came in, read through the pages they
     * came in (a packed page decodes on its first read); read-only.
     */
    static final class CheckedRows extends AbstractList<String[]> implements RandomAccess {
        private final List<List<String[]>> pages;
        /** The index of each page's first row. */
        private final int[] starts;
        private final int size;
        private final int width;

        private CheckedRows(List<List<String[]>> pages, int size, int width) {
            this.pages = List.copyOf(pages);
            this.starts = new int[this.pages.size()];
            int at = 0;
            for (int i = 0; i < starts.length; i++) {
                starts[i] = at;
                at += this.pages.get(i).size();
            }
            this.size = size;
            this.width = width;
        }

        int width() {
            return width;
        }

        @Override
        public String[] get(int index) {
            Objects.checkIndex(index, size);
            int page = Arrays.binarySearch(starts, index);
            if (page < 0) {
                page = -page - 2; // the page that starts before it
            }
            return pages.get(page).get(index - starts[page]);
        }

        @Override
        public int size() {
            return size;
        }

        @Override
        public Iterator<String[]> iterator() {
            return new Iterator<>() {
                private int page;
                private int row;

                @Override
                public boolean hasNext() {
                    return page < pages.size();
                }

                @Override
                public String[] next() {
                    if (!hasNext()) {
                        throw new NoSuchElementException();
                    }
                    List<String[]> p = pages.get(page);
                    String[] r = p.get(row++);
                    if (row == p.size()) {
                        page++;
                        row = 0;
                    }
                    return r;
                }
            };
        }
    }
}
