package org.ripv.client.trees;

import java.awt.event.MouseEvent;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreePath;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ConsoleModel;
import org.ripv.client.managers.ServiceModel;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.ServiceDescriptor;

/**
 * The SEL panel's tree of registered services (Appendix B, {@code ?services}): the server at the
 * root, one node per service with its description as a tooltip. Picking a service brings its
 * tab to the front. Rebuilt from the {@link ClientModel} on the event thread.
 */
public final class ServiceTree extends TickingTree {
    private final DefaultMutableTreeNode root = new DefaultMutableTreeNode("RIPVServer");
    private final DefaultTreeModel treeModel = new DefaultTreeModel(root);
    private boolean rebuilding;

    /** @param onSelect told of the service the operator picked */
    public ServiceTree(Consumer<String> onSelect) {
        this(onSelect, (service, mailbox) -> onSelect.accept(service));
    }

    /**
     * @param onSelect  told of the service the operator picked
     * @param onVehicle told of the service and MailBox when the operator picks a vehicle under a service
     */
    public ServiceTree(Consumer<String> onSelect, BiConsumer<String, String> onVehicle) {
        super("serviceTree");
        setModel(treeModel);
        setRootVisible(true);
        addTreeSelectionListener(e -> {
            Object picked = rebuilding ? null : picked(e);
            if (picked instanceof Item item) {
                onSelect.accept(item.descriptor().name());
            } else if (picked instanceof Vehicle v) {
                onVehicle.accept(v.service(), v.status().address());
            }
        });
    }

    /**
     * A vehicle MailBox under its service (one whose server state is known: it has published
     * console events): its handle, state badge and time since last contact.
     */
    public record Vehicle(String service, MailboxStatus status) {
        public String handle() {
            return status.address().startsWith(service) ? status.address().substring(service.length()) : status.address();
        }

        @Override
        public String toString() {
            return handle() + "  " + ConsoleModel.badge(status.session(), Instant.now());
        }
    }

    /** Re-words every node, so times since last contact stay current. */
    @Override
    public void tick() {
        for (int i = 0; i < root.getChildCount(); i++) {
            childrenChanged(treeModel, root.getChildAt(i));
        }
    }

    /** A service node; shows as its name. */
    public record Item(ServiceDescriptor descriptor) {
        @Override
        public String toString() {
            return descriptor.name();
        }
    }

    /** Rebuilds from the model, keeping the selection when the service is still there. */
    public void update(ClientModel model) {
        String selected = selectedService();
        String selectedVehicle = selectedVehicle();
        rebuilding = true;
        try {
            root.setUserObject(model.server().isEmpty() ? "RIPVServer" : "RIPVServer " + model.server());
            root.removeAllChildren();
            DefaultMutableTreeNode keep = null;
            List<DefaultMutableTreeNode> withVehicles = new ArrayList<>();
            for (ServiceModel s : model.services()) {
                DefaultMutableTreeNode n = new DefaultMutableTreeNode(new Item(s.descriptor()), true);
                root.add(n);
                if (s.name().equals(selected)) {
                    keep = n;
                }
                for (MailboxStatus m : s.mailboxes()) {
                    if (m.session() != null) {
                        DefaultMutableTreeNode v = new DefaultMutableTreeNode(new Vehicle(s.name(), m), false);
                        n.add(v);
                        if (m.address().equals(selectedVehicle)) {
                            keep = v;
                        }
                    }
                }
                if (n.getChildCount() > 0) {
                    withVehicles.add(n);
                }
            }
            treeModel.reload();
            expandRow(0);
            for (DefaultMutableTreeNode n : withVehicles) {
                expandPath(new TreePath(n.getPath()));
            }
            if (keep != null) {
                setSelectionPath(new TreePath(keep.getPath()));
            }
        } finally {
            rebuilding = false;
        }
    }

    /** Selects a service's node without telling the listener. */
    public void select(String service) {
        rebuilding = true;
        try {
            for (int i = 0; i < root.getChildCount(); i++) {
                DefaultMutableTreeNode n = (DefaultMutableTreeNode) root.getChildAt(i);
                if (((Item) n.getUserObject()).descriptor().name().equals(service)) {
                    setSelectionPath(new TreePath(n.getPath()));
                }
            }
        } finally {
            rebuilding = false;
        }
    }

    /** The selected service's name (or the service of the selected vehicle), or null. */
    public String selectedService() {
        TreePath p = getSelectionPath();
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n && n.getUserObject() instanceof Item i) {
            return i.descriptor().name();
        }
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n && n.getUserObject() instanceof Vehicle v) {
            return v.service();
        }
        return null;
    }

    /** The selected vehicle's MailBox address, or null. */
    public String selectedVehicle() {
        TreePath p = getSelectionPath();
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n && n.getUserObject() instanceof Vehicle v) {
            return v.status().address();
        }
        return null;
    }

    /** The vehicle nodes' words under a service, in order ("ru29  ● on call · last contact 3 min ago"). */
    public List<String> vehicles(String service) {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < root.getChildCount(); i++) {
            DefaultMutableTreeNode n = (DefaultMutableTreeNode) root.getChildAt(i);
            if (((Item) n.getUserObject()).descriptor().name().equals(service)) {
                for (int k = 0; k < n.getChildCount(); k++) {
                    out.add(((DefaultMutableTreeNode) n.getChildAt(k)).getUserObject().toString());
                }
            }
        }
        return out;
    }

    /** The services shown, in order. */
    public List<String> services() {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < root.getChildCount(); i++) {
            names.add(((Item) ((DefaultMutableTreeNode) root.getChildAt(i)).getUserObject()).descriptor().name());
        }
        return names;
    }

    @Override
    public String getToolTipText(MouseEvent e) {
        TreePath p = getPathForLocation(e.getX(), e.getY());
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n && n.getUserObject() instanceof Item i) {
            ServiceDescriptor d = i.descriptor();
            return d.description() + " (SID " + d.sid() + (d.panel().isEmpty() ? "" : ", " + d.panel()) + ")";
        }
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n && n.getUserObject() instanceof Vehicle v) {
            return v.status().address() + ": " + MailboxTree.sessionTip(v.status());
        }
        return null;
    }
}
