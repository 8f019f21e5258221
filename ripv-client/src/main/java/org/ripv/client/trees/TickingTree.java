package org.ripv.client.trees;

import javax.swing.JTree;
import javax.swing.Timer;
import javax.swing.ToolTipManager;
import javax.swing.event.TreeSelectionEvent;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreeNode;
import javax.swing.tree.TreePath;
import javax.swing.tree.TreeSelectionModel;

/**
 * A tree whose nodes say how long ago something happened ("last contact N min ago"): it is
 * re-worded every 30 s while it is shown, so those times move on by themselves.
 */
abstract class TickingTree extends JTree {
    private final Timer ticker = new Timer(30_000, e -> tick());

    /** A tree of one selection, with tooltips, that tests find by {@code name}. */
    TickingTree(String name) {
        setName(name);
        getSelectionModel().setSelectionMode(TreeSelectionModel.SINGLE_TREE_SELECTION);
        ToolTipManager.sharedInstance().registerComponent(this);
    }

    /** What the node the operator just picked holds, or null. */
    static Object picked(TreeSelectionEvent e) {
        TreePath p = e.getNewLeadSelectionPath();
        return p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n ? n.getUserObject() : null;
    }

    /** Re-words the nodes whose words change with time. */
    public abstract void tick();

    /** Tells the model that every child of {@code parent} may read differently now. */
    static void childrenChanged(DefaultTreeModel model, TreeNode parent) {
        int[] idx = new int[parent.getChildCount()];
        for (int k = 0; k < idx.length; k++) {
            idx[k] = k;
        }
        if (idx.length > 0) {
            model.nodesChanged(parent, idx);
        }
    }

    @Override
    public void addNotify() {
        super.addNotify();
        ticker.start();
    }

    @Override
    public void removeNotify() {
        ticker.stop();
        super.removeNotify();
    }
}
