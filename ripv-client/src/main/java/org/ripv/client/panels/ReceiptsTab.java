package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.Font;
import java.awt.event.KeyEvent;
import java.util.Collections;
import java.util.List;
import javax.swing.DefaultListCellRenderer;
import javax.swing.DefaultListModel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSpinner;
import javax.swing.JSplitPane;
import javax.swing.JTextArea;
import javax.swing.ListSelectionModel;
import javax.swing.SpinnerNumberModel;
import org.ripv.client.managers.WorkflowModel;

/**
 * The workflow window's Receipts tab: the receipts {@code ?receipts --last N} listed (one that had
 * errors in the error colour), the chosen one's text beside them, and how many to ask for.
 */
final class ReceiptsTab extends JPanel {
    private final DefaultListModel<WorkflowModel.Receipt> receipts = new DefaultListModel<>();
    private final JList<WorkflowModel.Receipt> receiptList = new JList<>(receipts);
    private final JTextArea receiptText = new JTextArea();
    private final JSpinner last = new JSpinner(new SpinnerNumberModel(20, 1, 1000, 5));
    private final JSplitPane split;

    /** {@code refresh}: asks the server again (the Refresh button). */
    ReceiptsTab(Runnable refresh) {
        super(new BorderLayout(4, 4));
        receiptList.setName("receiptList");
        receiptList.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        receiptList.setCellRenderer(new DefaultListCellRenderer() {
            @Override
            public Component getListCellRendererComponent(JList<?> list, Object value, int index,
                                                                   boolean selected, boolean focus) {
                Component c = super.getListCellRendererComponent(list, value, index, selected, focus);
                if (!selected && value instanceof WorkflowModel.Receipt r && r.hadErrors()) {
                    c.setForeground(Colors.error()); // DONE_WITH_ERRORS must not read like DONE
                }
                return c;
            }
        });
        receiptList.addListSelectionListener(e -> {
            WorkflowModel.Receipt r = receiptList.getSelectedValue();
            receiptText.setText(r == null ? "" : r.text());
            receiptText.setCaretPosition(0);
        });
        receiptText.setName("receiptText");
        receiptText.setEditable(false);
        receiptText.setFont(new Font(Font.MONOSPACED, Font.PLAIN, receiptText.getFont().getSize()));
        split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, new JScrollPane(receiptList), new JScrollPane(receiptText));
        split.setResizeWeight(0.4);
        split.setBorder(null);
        JPanel buttons = WorkflowDialog.row("Last:", KeyEvent.VK_T, last, Buttons.button("Refresh", KeyEvent.VK_H,
                "receiptsRefresh", "Ask the server again (?receipts --last N)", e -> refresh.run()));
        WorkflowDialog.lay(this, split, buttons, BorderLayout.SOUTH);
    }

    /** The list takes 40 % once the window has its size. */
    void split() {
        split.setDividerLocation(0.4);
    }

    /** How many receipts to ask for. */
    int last() {
        return (Integer) last.getValue();
    }

    /** Shows the receipts the server listed, keeping the one chosen when it is still there. */
    void show(List<WorkflowModel.Receipt> now) {
        WorkflowModel.Receipt shown = receiptList.getSelectedValue();
        if ((!receipts.isEmpty() || !now.isEmpty()) && !now.equals(Collections.list(receipts.elements()))) {
            receipts.clear();
            now.forEach(receipts::addElement);
            int keep = shown == null ? -1 : now.indexOf(shown);
            receiptList.setSelectedIndex(keep >= 0 ? keep : now.isEmpty() ? -1 : 0);
        }
    }

    /** The receipts listed, as their titles. */
    List<String> titles() {
        return Collections.list(receipts.elements()).stream().map(Object::toString).toList();
    }
}
