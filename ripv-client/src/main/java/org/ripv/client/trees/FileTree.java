package org.ripv.client.trees;

import java.awt.event.MouseEvent;
import java.text.SimpleDateFormat;
import java.util.ArrayList;
import java.util.Date;
import java.util.List;
import java.util.Locale;
import javax.swing.JTree;
import javax.swing.ToolTipManager;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreePath;
import javax.swing.tree.TreeSelectionModel;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.messages.FileListing;

/**
 * The FIM panel's FileTree (thesis 4.1.3.3, Appendix B {@code ?uldir ?dldir ?ulfiles
 * ?dlfiles}): the server's upload and download directories as two root nodes, their files below.
 */
public final class FileTree extends JTree {
    private final DefaultMutableTreeNode root = new DefaultMutableTreeNode("RIPVServer files");
    private final DefaultTreeModel treeModel = new DefaultTreeModel(root);

    /** A directory node. */
    public record Dir(FileArea area, String path, int count) {
        @Override
        public String toString() {
            return area.label() + "  " + (path.isBlank() ? "(unknown)" : path) + "  (" + count + ")";
        }
    }

    /** A file node. */
    public record File(FileArea area, FileListing.Entry entry) {
        @Override
        public String toString() {
            return entry.name() + "  " + size(entry.size());
        }
    }

    public FileTree() {
        setModel(treeModel);
        setName("fileTree");
        setRootVisible(false);
        setShowsRootHandles(true);
        getSelectionModel().setSelectionMode(TreeSelectionModel.SINGLE_TREE_SELECTION);
        ToolTipManager.sharedInstance().registerComponent(this);
    }

    /** Rebuilds both directories from the model; keeps the selected file when it is still listed. */
    public void update(ClientModel model) {
        File selected = selectedFile();
        root.removeAllChildren();
        DefaultMutableTreeNode keep = null;
        for (FileArea area : FileArea.values()) {
            ClientModel.Directory d = model.directory(area);
            DefaultMutableTreeNode dir = new DefaultMutableTreeNode(new Dir(area, d.path(), d.files().size()));
            for (FileListing.Entry e : d.files()) {
                DefaultMutableTreeNode n = new DefaultMutableTreeNode(new File(area, e), false);
                dir.add(n);
                if (selected != null && selected.area() == area && selected.entry().name().equals(e.name())) {
                    keep = n;
                }
            }
            root.add(dir);
        }
        treeModel.reload();
        for (int i = 0; i < getRowCount(); i++) {
            expandRow(i);
        }
        if (keep != null) {
            setSelectionPath(new TreePath(keep.getPath()));
        }
    }

    /** The selected file, or null when a directory or nothing is selected. */
    public File selectedFile() {
        TreePath p = getSelectionPath();
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n && n.getUserObject() instanceof File f) {
            return f;
        }
        return null;
    }

    /** Names listed under one directory. */
    public List<String> names(FileArea area) {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < root.getChildCount(); i++) {
            DefaultMutableTreeNode dir = (DefaultMutableTreeNode) root.getChildAt(i);
            if (((Dir) dir.getUserObject()).area() == area) {
                for (int j = 0; j < dir.getChildCount(); j++) {
                    out.add(((File) ((DefaultMutableTreeNode) dir.getChildAt(j)).getUserObject()).entry().name());
                }
            }
        }
        return out;
    }

    /** Selects a file by area and name. */
    public void select(FileArea area, String name) {
        for (int i = 0; i < root.getChildCount(); i++) {
            DefaultMutableTreeNode dir = (DefaultMutableTreeNode) root.getChildAt(i);
            for (int j = 0; j < dir.getChildCount(); j++) {
                DefaultMutableTreeNode n = (DefaultMutableTreeNode) dir.getChildAt(j);
                File f = (File) n.getUserObject();
                if (f.area() == area && f.entry().name().equals(name)) {
                    setSelectionPath(new TreePath(n.getPath()));
                    return;
                }
            }
        }
        throw new IllegalArgumentException("no file '" + name + "' under " + area.label());
    }

    @Override
    public String getToolTipText(MouseEvent e) {
        TreePath p = getPathForLocation(e.getX(), e.getY());
        if (p != null && p.getLastPathComponent() instanceof DefaultMutableTreeNode n) {
            if (n.getUserObject() instanceof File f) {
                return f.entry().name() + ", " + f.entry().size() + " bytes, "
                        + new SimpleDateFormat("yyyy-MM-dd HH:mm:ss", Locale.ROOT).format(new Date(f.entry().modified()));
            }
            if (n.getUserObject() instanceof Dir d) {
                return d.area() == FileArea.UPLOAD ? "UL: files uploaded to the server, for services to use"
                        : "DL: files the services sent back to the server";
            }
        }
        return null;
    }

    /** "1.5 MB" and friends. */
    public static String size(long bytes) {
        if (bytes < 1024) {
            return bytes + " B";
        }
        double v = bytes;
        String[] units = {"KB", "MB", "GB", "TB"};
        int u = -1;
        while (v >= 1024 && u < units.length - 1) {
            v /= 1024;
            u++;
        }
        return String.format(Locale.ROOT, "%.1f %s", v, units[u]);
    }
}
