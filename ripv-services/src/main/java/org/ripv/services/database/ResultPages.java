package org.ripv.services.database;

import java.time.Duration;
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

    private final Request request;
    private int maxRows = FIRST_PAGE_ROWS;
    private long maxChars = MAX_PAGE_CHARS / 32;
    private int sent;
    private int pages;

    ResultPages(Request request) {
        this.request = request;
    }

    /** Whether a page of {@code rows} rows weighing {@code chars} is full, so that it goes before the next row. */
    boolean full(int rows, long chars) {
        return request != null && rows > 0 && (rows >= maxRows || chars >= maxChars);
    }

    /** Sends a full page once the reader has room for it; the next page may be twice as large. */
    void send(TableResult page) throws Request.PagesStopped, InterruptedException {
        int first = sent + 1;
        sent += page.rows().size();
        pages++;
        request.page("rows " + first + "-" + sent, page, READER_WAIT);
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
