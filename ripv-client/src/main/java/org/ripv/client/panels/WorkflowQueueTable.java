package org.ripv.client.panels;

import java.util.List;
import javax.swing.table.AbstractTableModel;
import org.ripv.client.managers.WorkflowModel;

/** A MailBox's workflow queue as a table: ID, owner, mode, file, steps, state. */
final class WorkflowQueueTable extends AbstractTableModel {
    private static final String[] COLUMNS = {"ID", "Owner", "Mode", "File", "Steps", "State"};
    private List<WorkflowModel.Entry> rows = List.of();

    void show(List<WorkflowModel.Entry> entries) {
        if (!entries.equals(rows)) {
            rows = entries;
            fireTableDataChanged();
        }
    }

    /** The workflow on a row. */
    WorkflowModel.Entry entry(int row) {
        return rows.get(row);
    }

    @Override
    public int getRowCount() {
        return rows.size();
    }

    @Override
    public int getColumnCount() {
        return COLUMNS.length;
    }

    @Override
    public String getColumnName(int c) {
        return COLUMNS[c];
    }

    @Override
    public Object getValueAt(int r, int c) {
        WorkflowModel.Entry e = rows.get(r);
        return switch (c) {
            case 0 -> e.id();
            case 1 -> e.owner();
            case 2 -> e.mode();
            case 3 -> e.file();
            case 4 -> e.steps();
            default -> e.state() + (e.added().isEmpty() ? "" : "  (added " + e.added() + ")");
        };
    }
}
