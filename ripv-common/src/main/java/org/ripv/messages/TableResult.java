package org.ripv.messages;

import java.io.Serial;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * A query's answer: column names and SQL type names, rows of values rendered as text (null for
 * SQL NULL), and whether the rows were cut at the service's limit.
 *
 * <p>The rows are kept as given when they are {@link PackedRows} (as a query's pages travel: packed
 * by the service, unpacked where they are read) or rows {@link TablePages} joined and checked;
 * any other list is copied and checked here.
 */
public record TableResult(String query, List<String> columns, List<String> types, List<String[]> rows,
                          boolean truncated) implements Result {
    public TableResult {
        query = query == null ? "" : query;
        columns = List.copyOf(columns);
        types = List.copyOf(types);
        if (columns.size() != types.size()) {
            throw new IllegalArgumentException(columns.size() + " columns but " + types.size() + " types");
        }
        if (rows instanceof PackedRows p) {
            if (p.width() != columns.size()) {
                throw new IllegalArgumentException("every row needs " + columns.size() + " values, the packed rows have "
                        + p.width());
            }
        } else if (!(rows instanceof TablePages.CheckedRows c && c.width() == columns.size())) {
            List<String[]> copy = new ArrayList<>(rows.size());
            for (String[] row : rows) {
                if (row == null || row.length != columns.size()) {
                    throw new IllegalArgumentException("every row needs " + columns.size() + " values");
                }
                copy.add(row);
            }
            rows = Collections.unmodifiableList(copy);
        }
    }

    /** Travels as one packed byte array rather than an object per cell ({@link PackedTable}). */
    @Serial
    private Object writeReplace() {
        return new PackedTable(this);
    }
}
