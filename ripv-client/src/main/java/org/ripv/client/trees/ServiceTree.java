package org.ripv.client.trees;

import java.util.function.Consumer;
import javax.swing.JTree;
import javax.swing.ToolTipManager;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreePath;
import javax.swing.tree.TreeSelectionModel;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ServiceModel;
import org.ripv.messages.ServiceDescriptor;

/**
 * The SEL panel's tree of registered services (Appendix B, {@code ?services}): the server at the
 * root, one node per service with its description as a tooltip. Picking a service brings its
 * tab to the front. Rebuilt from the {@link ClientModel} on the event thread.
 */
public final class ServiceTree extends JTree {
    private final DefaultMutableTreeNode root = new DefaultMutableTreeNode("RIPVServer");
    private final DefaultTreeModel treeModel = new DefaultTreeModel(root);
    private boolean rebuilding;

    /** @param onSelect told of the service the operator picked */
    public ServiceTree(Consumer<String> onSelect) {
        setModel(treeModel);
        setName("serviceTree");
        setRootVisible(true);
        getSelectionModel().setSelectionMode(TreeSelectionModel.SINGLE_TREE_SELECTION);
        ToolTipManager.sharedInstance().registerComponent(this);
        addTreeSelectionListener(e -> {
            if (!rebuilding && e.getNewLeadSelectionPath() != null
                    && e.getNewLeadSelectionPath().getLastPathComponent() instanceof DefaultMutableTreeNode n
                    && n.getUserObject() instanceof Item item) {
                onSelect.accept(item.descriptor().name());
            }
        });
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
        rebuilding = true;
        try {
            root.setUserObject(model.server().isEmpty() ? "RIPVServer" : "RIPVServer " + model.server());
            root.removeAllChildren();
            DefaultMutableTreeNode keep = null;
            for (ServiceModel s : model.services()) {
                DefaultMutableTreeNode n = new DefaultMutableTreeNode(new Item(s.descriptor()), false);
                root.add(n);
                if (s.name().equals(selected)) {
                    keep = n;
                }
            }
            treeModel.reload();
            expandRow(0);
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

    /** The selected service's name, or null. */
    public String selectedService() {
        TreePath p = getSelectionPath();
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n && n.getUserObject() instanceof Item i) {
            return i.descriptor().name();
        }
        return null;
    }

    /** The services shown, in order. */
    public java.util.List<String> services() {
        java.util.List<String> names = new java.util.ArrayList<>();
        for (int i = 0; i < root.getChildCount(); i++) {
            names.add(((Item) ((DefaultMutableTreeNode) root.getChildAt(i)).getUserObject()).descriptor().name());
        }
        return names;
    }

    @Override
    public String getToolTipText(java.awt.event.MouseEvent e) {
        TreePath p = getPathForLocation(e.getX(), e.getY());
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n && n.getUserObject() instanceof Item i) {
            ServiceDescriptor d = i.descriptor();
            return d.description() + " (SID " + d.sid() + (d.panel().isEmpty() ? "" : ", " + d.panel()) + ")";
        }
        return null;
    }
}
