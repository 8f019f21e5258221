package org.ripv.client.panels;

import java.awt.Font;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import org.ripv.client.managers.ConsoleModel;
import org.ripv.messages.ConsoleEntry;

/**
 * The workflow window's view of the live console: a MailBox's workflow progress lines and its
 * WORKFLOW_DONE / _DONE_WITH_ERRORS / _FAILED events, newest last.
 */
final class WorkflowEvents extends JScrollPane {
    private final JTextArea events = new JTextArea(5, 40);
    private String lastWorkflowEntry = "";

    WorkflowEvents() {
        events.setName("workflowEvents");
        events.setEditable(false);
        events.setFont(new Font(Font.MONOSPACED, Font.PLAIN, events.getFont().getSize()));
        setViewportView(events);
        setBorder(BorderFactory.createTitledBorder("Workflow lines and events (live console)"));
    }

    /**
     * Shows the workflow lines and events among a MailBox's console entries.
     *
     * @return true when one arrived since the last time (not on the first showing): the queue has moved on
     */
    boolean show(List<ConsoleEntry> entries) {
        StringBuilder b = new StringBuilder();
        String newest = "";
        for (ConsoleEntry e : entries) {
            if (isWorkflow(e)) {
                String line = ConsoleModel.text(e);
                b.append(line).append('\n');
                newest = line;
            }
        }
        if (newest.equals(lastWorkflowEntry)) {
            return false;
        }
        boolean first = lastWorkflowEntry.isEmpty() && events.getText().isEmpty();
        lastWorkflowEntry = newest;
        events.setText(b.toString());
        events.setCaretPosition(events.getDocument().getLength());
        return !first;
    }

    String text() {
        return events.getText();
    }

    /** A workflow's progress line ("workflow 1 'x.wf': step 2/4 …") or a WORKFLOW_DONE / _DONE_WITH_ERRORS / _FAILED event. */
    static boolean isWorkflow(ConsoleEntry e) {
        return e.kind() == ConsoleEntry.Kind.EVENT
                ? e.event().endsWorkflow()
                : e.kind() == ConsoleEntry.Kind.COMMAND && e.text().startsWith("workflow ");
    }
}
