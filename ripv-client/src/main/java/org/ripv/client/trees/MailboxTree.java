package org.ripv.client.trees;

import java.awt.event.MouseEvent;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreePath;
import org.ripv.client.managers.ConsoleModel;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.SessionState;

/**
 * The MAM panel's tree (thesis 4.1.3.2): the service at the root, one node per MailBox, each
 * showing its handle and whether it is available, busy or locked. Picking a MailBox makes it the
 * COM panel's target (the GuiManager then asks {@code ?status}).
 */
public final class MailboxTree extends TickingTree {
    private final DefaultMutableTreeNode root;
    private final DefaultTreeModel treeModel;
    private final String service;
    private boolean rebuilding;

    /** A MailBox node: shows its handle and status. */
    public record Item(String service, MailboxStatus status) {
        public String handle() {
            return status.address().startsWith(service) ? status.address().substring(service.length()) : status.address();
        }

        @Override
        public String toString() {
            String s = handle() + (status.available() ? "" : "  (not available)");
            if (status.busy()) {
                s += "  [busy]";
            }
            if (!status.lockedBy().isBlank()) {
                s += "  [locked by " + status.lockedBy() + "]";
            }
            if (status.session() != null) {
                s += "  " + ConsoleModel.badge(status.session(), Instant.now());
            }
            return s;
        }
    }

    /** @param onSelect told of the full address of the MailBox the operator picked */
    public MailboxTree(String service, Consumer<String> onSelect) {
        super("mailboxTree");
        this.service = service;
        this.root = new DefaultMutableTreeNode(service);
        this.treeModel = new DefaultTreeModel(root);
        setModel(treeModel);
        addTreeSelectionListener(e -> {
            if (!rebuilding && picked(e) instanceof Item item) {
                onSelect.accept(item.status().address());
            }
        });
    }

    /** Shows the service's MailBoxes and selects the target. */
    public void update(List<MailboxStatus> mailboxes, String target) {
        rebuilding = true;
        try {
            root.removeAllChildren();
            DefaultMutableTreeNode selected = null;
            for (MailboxStatus m : mailboxes) {
                DefaultMutableTreeNode n = new DefaultMutableTreeNode(new Item(service, m), false);
                root.add(n);
                if (m.address().equals(target)) {
                    selected = n;
                }
            }
            treeModel.reload();
            expandRow(0);
            if (selected != null) {
                setSelectionPath(new TreePath(selected.getPath()));
            } else {
                clearSelection();
            }
        } finally {
            rebuilding = false;
        }
    }

    /** The handles shown, in order. */
    public List<String> handles() {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < root.getChildCount(); i++) {
            out.add(((Item) ((DefaultMutableTreeNode) root.getChildAt(i)).getUserObject()).handle());
        }
        return out;
    }

    /** Selects a MailBox by handle, as the operator would (the listener is told). */
    public void pick(String handle) {
        for (int i = 0; i < root.getChildCount(); i++) {
            DefaultMutableTreeNode n = (DefaultMutableTreeNode) root.getChildAt(i);
            if (((Item) n.getUserObject()).handle().equals(handle)) {
                setSelectionPath(new TreePath(n.getPath()));
                return;
            }
        }
        throw new IllegalArgumentException("no mailbox '" + handle + "' under " + service);
    }

    /** "on call, last contact 2026-…Z, at 41.63323, -70.53647, 3 calls this run": a vehicle node's tooltip. */
    public static String sessionTip(MailboxStatus s) {
        SessionState st = s.session();
        if (st == null) {
            return "";
        }
        StringBuilder b = new StringBuilder(st.state().words());
        if (st.lastContact() > 0) {
            b.append(", last contact ").append(Instant.ofEpochMilli(st.lastContact()));
        }
        if (st.hasPosition()) {
            b.append(String.format(Locale.ROOT, ", at %.5f, %.5f", st.lat(), st.lon()));
        }
        return b.append(", ").append(st.calls()).append(st.calls() == 1 ? " call" : " calls").append(" this run").toString();
    }

    /** Re-words every node, so times since last contact stay current. */
    @Override
    public void tick() {
        childrenChanged(treeModel, root);
    }

    @Override
    public String getToolTipText(MouseEvent e) {
        TreePath p = getPathForLocation(e.getX(), e.getY());
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n && n.getUserObject() instanceof Item i) {
            MailboxStatus s = i.status();
            // A vehicle's line is its call state (as SS and the badge say it), the service's word on the call left out.
            return s.address() + ": " + (s.session() == null ? (s.available() ? "available" : "not available")
                    + (s.detail().isBlank() ? "" : " — " + s.detail()) : sessionTip(s));
        }
        return "Pick a MailBox to talk to (it becomes Talking To, TT)";
    }
}
