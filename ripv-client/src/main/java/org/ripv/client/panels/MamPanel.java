package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GridLayout;
import java.awt.event.KeyEvent;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.SwingUtilities;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;
import org.ripv.client.trees.MailboxTree;

/**
 * The MAilbox Management panel (thesis 4.1.3.2): the service's MailBoxes in a
 * {@link MailboxTree}; picking one makes it the COM panel's target. Lock and Unlock take and
 * release the operator lock on the target ({@code ?lock}, {@code ?unlock}).
 */
public final class MamPanel extends JPanel {
    private final MailboxTree tree;
    private final JButton lock = new JButton("Lock");
    private final JButton unlock = new JButton("Unlock");
    private final JButton queue = new JButton("Queue…");
    private WorkflowDialog workflows;
    private String target = "";

    public MamPanel(String service, GuiManager manager) {
        super(new BorderLayout(4, 4));
        setName("mam");
        setBorder(BorderFactory.createTitledBorder("MAM — mailboxes"));
        tree = new MailboxTree(service, mailbox -> manager.selectMailbox(service, mailbox));
        JScrollPane scroll = new JScrollPane(tree);
        scroll.setPreferredSize(new Dimension(260, 120));
        add(scroll, BorderLayout.CENTER);

        JButton refresh = Buttons.button("Refresh", KeyEvent.VK_H, "mamRefresh",
                "Ask the server again for the services and their MailBoxes (?services, ?mailboxes)", e -> manager.refreshServices());
        lock.setName("lockButton");
        lock.setMnemonic(KeyEvent.VK_L);
        lock.setToolTipText("Hold the target MailBox for yourself so others cannot command it meanwhile (?lock)");
        lock.addActionListener(e -> manager.sendCommand(service, "?lock " + target));
        unlock.setName("unlockButton");
        unlock.setMnemonic(KeyEvent.VK_K);
        unlock.setToolTipText("Release your lock on the target MailBox (?unlock)");
        unlock.addActionListener(e -> manager.sendCommand(service, "?unlock " + target));
        queue.setName("queueButton");
        queue.setMnemonic(KeyEvent.VK_Q);
        queue.setToolTipText("The target MailBox's workflow queue and receipts: list, add (a file or written here), remove, clear");
        queue.addActionListener(e -> openWorkflows(manager));
        // Two rows, so every button shows in a narrow quadrant (1280×800) as FIM's do.
        JPanel buttons = new JPanel(new GridLayout(2, 2, 4, 2));
        buttons.add(refresh);
        buttons.add(queue);
        buttons.add(lock);
        buttons.add(unlock);
        add(buttons, BorderLayout.SOUTH);
    }

    /** Repaints from the model; on the event thread. */
    public void update(ServiceModel m) {
        target = m.target();
        tree.update(m.mailboxes(), m.target());
        lock.setEnabled(!target.isEmpty());
        unlock.setEnabled(!target.isEmpty());
        queue.setEnabled(!target.isEmpty());
    }

    /** Opens (or brings to the front) the workflow window of the target MailBox. */
    public WorkflowDialog openWorkflows(GuiManager manager) {
        if (target.isEmpty()) {
            return null;
        }
        if (workflows == null || !workflows.isDisplayable() || !workflows.mailbox().equals(target)) {
            if (workflows != null) {
                workflows.dispose();
            }
            workflows = new WorkflowDialog(SwingUtilities.getWindowAncestor(this), manager, target);
        }
        workflows.setVisible(true);
        workflows.toFront();
        return workflows;
    }

    /** The workflow window the Queue button opened, or null while none is showing. */
    public WorkflowDialog workflowsWindow() {
        return workflows != null && workflows.isShowing() ? workflows : null;
    }

    public MailboxTree tree() {
        return tree;
    }
}
