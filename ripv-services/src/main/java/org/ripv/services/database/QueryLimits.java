package org.ripv.services.database;

/**
 * How much one SQL command may take.
 *
 * @param maxRows             rows a query returns at most; more are cut and the table marked
 *                            truncated ({@code setMaxRows(maxRows + 1)} tells there were more)
 * @param queryTimeoutSeconds seconds a statement may run before the database cancels it (0: no limit)
 * @param maxResultChars      characters of cell text one table may carry at most, so that the
 *                            reply fits in one socket frame (16 MiB by default); a table cut
 *                            here is marked truncated too
 */
public record QueryLimits(int maxRows, int queryTimeoutSeconds, long maxResultChars) {
    public static final int DEFAULT_MAX_ROWS = 10_000;
    public static final int DEFAULT_QUERY_TIMEOUT_SECONDS = 30;
    /** Leaves room under the 16 MiB frame for Java serialization's per-string overhead. */
    public static final long DEFAULT_MAX_RESULT_CHARS = 8L * 1024 * 1024;

    public QueryLimits {
        if (maxRows < 1 || maxRows == Integer.MAX_VALUE) {
            throw new IllegalArgumentException("max rows must be 1 .. " + (Integer.MAX_VALUE - 1) + ", got " + maxRows);
        }
        if (queryTimeoutSeconds < 0) {
            throw new IllegalArgumentException("the query timeout is seconds >= 0, got " + queryTimeoutSeconds);
        }
        if (maxResultChars < 1) {
            throw new IllegalArgumentException("max result characters must be positive, got " + maxResultChars);
        }
    }

    public static QueryLimits defaults() {
        return new QueryLimits(DEFAULT_MAX_ROWS, DEFAULT_QUERY_TIMEOUT_SECONDS, DEFAULT_MAX_RESULT_CHARS);
    }
}
