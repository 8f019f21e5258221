package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JScrollPane;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.Transfer;
import org.ripv.client.trees.FileTree;

/**
 * The FIle Management panel (thesis 4.1.3.3): a {@link FileTree} of the server's upload and
 * download directories; UL uploads a file from this computer to the server's upload directory,
 * DL downloads the selected file to this computer; each transfer has a progress bar and a
 * Cancel button. Every service's FIM panel shows the same server-wide directories.
 */
public final class FimPanel extends JPanel {
    private final GuiManager manager;
    private final FileTree tree = new FileTree();
    private final JPanel transfers = new JPanel();
    private final Map<Long, Row> rows = new HashMap<>();
    private Path lastDir = Path.of(System.getProperty("user.home"));

    private record Row(JPanel panel, JProgressBar bar, JLabel label, JButton cancel) {}

    public FimPanel(GuiManager manager) {
        super(new BorderLayout(4, 4));
        this.manager = manager;
        setName("fim");
        setBorder(BorderFactory.createTitledBorder("FIM — files on the server"));
        JScrollPane scroll = new JScrollPane(tree);
        scroll.setPreferredSize(new java.awt.Dimension(260, 140));
        add(scroll, BorderLayout.CENTER);

        JButton ul = new JButton("UL");
        ul.setName("ulButton");
        ul.setToolTipText("UL: upload a file from this computer to the server's upload directory");
        ul.addActionListener(e -> chooseUpload());
        JButton dl = new JButton("DL");
        dl.setName("dlButton");
        dl.setToolTipText("DL: download the selected file from the server to this computer");
        dl.addActionListener(e -> chooseDownload());
        JButton refresh = new JButton("Refresh");
        refresh.setName("fimRefresh");
        refresh.setToolTipText("List the server's upload and download directories again (?ulfiles, ?dlfiles)");
        refresh.addActionListener(e -> manager.refreshFiles());
        JButton clear = new JButton("Clear done");
        clear.setToolTipText("Remove finished transfers from the list");
        clear.addActionListener(e -> manager.clearFinishedTransfers());
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        buttons.add(ul);
        buttons.add(dl);
        buttons.add(refresh);
        buttons.add(clear);

        tree.addMouseListener(new MouseAdapter() {
            @Override
            public void mouseClicked(MouseEvent e) {
                if (e.getClickCount() == 2 && tree.selectedFile() != null) {
                    chooseDownload();
                }
            }
        });

        transfers.setName("transfers");
        transfers.setLayout(new BoxLayout(transfers, BoxLayout.Y_AXIS));
        JPanel south = new JPanel(new BorderLayout(0, 2));
        south.add(transfers, BorderLayout.CENTER);
        south.add(buttons, BorderLayout.SOUTH);
        add(south, BorderLayout.SOUTH);
    }

    private void chooseUpload() {
        JFileChooser chooser = new JFileChooser(lastDir.toFile());
        chooser.setDialogTitle("Upload to the server's upload directory");
        if (chooser.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) {
            Path file = chooser.getSelectedFile().toPath();
            lastDir = file.toAbsolutePath().getParent();
            manager.upload(file);
        }
    }

    private void chooseDownload() {
        FileTree.File f = tree.selectedFile();
        if (f == null) {
            manager.showNotice("pick a file in the FIM tree first, then DL", true);
            return;
        }
        if (f.area() == FileArea.UPLOAD) {
            manager.showNotice("DL fetches from the download directory; " + f.entry().name()
                    + " is in the upload directory", true);
            return;
        }
        JFileChooser chooser = new JFileChooser(lastDir.toFile());
        chooser.setDialogTitle("Download " + f.entry().name() + " into");
        chooser.setFileSelectionMode(JFileChooser.DIRECTORIES_ONLY);
        if (chooser.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            lastDir = chooser.getSelectedFile().toPath();
            manager.download(f.entry().name(), lastDir);
        }
    }

    /** Repaints the tree from the model; on the event thread. */
    public void updateFiles(ClientModel model) {
        tree.update(model);
    }

    /** Repaints the transfers; on the event thread. */
    public void updateTransfers(ClientModel model) {
        java.util.Set<Long> seen = new java.util.HashSet<>();
        for (Transfer t : model.transfers()) {
            seen.add(t.id());
            Row r = rows.computeIfAbsent(t.id(), id -> newRow(t));
            r.bar().setIndeterminate(t.percent() < 0 && !t.finished());
            r.bar().setValue(Math.max(0, t.percent()));
            r.bar().setString(t.finished() ? t.state().name().toLowerCase(java.util.Locale.ROOT)
                    : (t.percent() < 0 ? "starting" : t.percent() + "%  " + FileTree.size(t.done())
                    + " / " + FileTree.size(t.total())));
            r.label().setToolTipText(t.detail().isEmpty() ? null : t.detail());
            r.bar().setToolTipText(t.detail().isEmpty() ? null : t.detail());
            r.cancel().setEnabled(!t.finished() && !t.cancelRequested());
        }
        rows.entrySet().removeIf(e -> {
            if (!seen.contains(e.getKey())) {
                transfers.remove(e.getValue().panel());
                return true;
            }
            return false;
        });
        transfers.revalidate();
        transfers.repaint();
    }

    private Row newRow(Transfer t) {
        JPanel p = new JPanel(new BorderLayout(4, 0));
        JLabel label = new JLabel((t.direction() == Transfer.Direction.UPLOAD ? "UL " : "DL ") + t.name());
        JProgressBar bar = new JProgressBar(0, 100);
        bar.setName("transfer-" + t.name());
        bar.setStringPainted(true);
        JButton cancel = new JButton("Cancel");
        cancel.setToolTipText("Stop this transfer; nothing partial is kept");
        cancel.addActionListener(e -> {
            t.cancel();
            cancel.setEnabled(false);
        });
        p.add(label, BorderLayout.WEST);
        p.add(bar, BorderLayout.CENTER);
        p.add(cancel, BorderLayout.EAST);
        p.setBorder(BorderFactory.createEmptyBorder(1, 0, 1, 0));
        transfers.add(p);
        return new Row(p, bar, label, cancel);
    }

    public FileTree tree() {
        return tree;
    }
}
