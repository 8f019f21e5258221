package org.ripv.client.panels;

import java.util.List;
import javax.swing.JTable;
import org.ripv.export.TableExport;
import org.ripv.messages.TableResult;

/** Renders a query's rows as CSV (RFC 4180) for export, and as tab-separated text for the clipboard. */
public final class TableText {
    private TableText() {}

    /** The whole table, header first, CRLF line ends, SQL NULL as an empty field ({@link org.ripv.export.TableExport}). */
    public static String csv(TableResult t) {
        return TableExport.csv(t);
    }

    /** One CSV field, quoted when it needs it. */
    public static String csvField(String v) {
        return TableExport.field(v);
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
