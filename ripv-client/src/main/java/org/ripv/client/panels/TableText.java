package org.ripv.client.panels;

import java.util.List;
import javax.swing.JTable;
import org.ripv.messages.TableResult;

/** Renders a query's rows as CSV (RFC 4180) for export, and as tab-separated text for the clipboard. */
public final class TableText {
    private TableText() {}

    /** The whole table, header first, CRLF line ends, SQL NULL as an empty field. */
    public static String csv(TableResult t) {
        StringBuilder b = new StringBuilder();
        row(b, t.columns().toArray(String[]::new));
        for (String[] r : t.rows()) {
            row(b, r);
        }
        return b.toString();
    }

    private static void row(StringBuilder b, String[] values) {
        for (int i = 0; i < values.length; i++) {
            if (i > 0) {
                b.append(',');
            }
            b.append(csvField(values[i]));
        }
        b.append("\r\n");
    }

    /** One CSV field, quoted when it holds a comma, quote or line break. */
    public static String csvField(String v) {
        if (v == null) {
            return "";
        }
        if (v.indexOf(',') >= 0 || v.indexOf('"') >= 0 || v.indexOf('\n') >= 0 || v.indexOf('\r') >= 0
                || (!v.isEmpty() && (Character.isWhitespace(v.charAt(0)) || Character.isWhitespace(v.charAt(v.length() - 1))))) {
            return '"' + v.replace("\"", "\"\"") + '"';
        }
        return v;
    }

    /** The selected rows (all when none is selected) as TSV with a header line, in view order. */
    public static String tsv(JTable table, List<String> columns) {
        StringBuilder b = new StringBuilder(String.join("\t", columns)).append('\n');
        int[] rows = table.getSelectedRows();
        if (rows.length == 0) {
            rows = new int[table.getRowCount()];
            for (int i = 0; i < rows.length; i++) {
                rows[i] = i;
            }
        }
        for (int viewRow : rows) {
            int r = table.convertRowIndexToModel(viewRow);
            for (int c = 0; c < columns.size(); c++) {
                if (c > 0) {
                    b.append('\t');
                }
                Object v = table.getModel().getValueAt(r, c);
                b.append(v == null ? "" : v.toString().replace('\t', ' ').replace('\n', ' '));
            }
            b.append('\n');
        }
        return b.toString();
    }
}
