package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GridLayout;
import java.awt.event.ActionEvent;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import org.ripv.client.handlers.ClientSocketHandler;
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
        scroll.setPreferredSize(new Dimension(260, 140));
        add(scroll, BorderLayout.CENTER);

        JButton ul = Buttons.button("UL", KeyEvent.VK_U, "ulButton",
                "UL: upload a file from this computer to the server's upload directory", e -> chooseUpload());
        JButton dl = Buttons.button("DL", KeyEvent.VK_D, "dlButton",
                "DL: download the selected file from the server to this computer", e -> chooseDownload());
        JButton refresh = Buttons.button("Refresh", KeyEvent.VK_I, "fimRefresh",
                "List the server's upload and download directories again (?ulfiles, ?dlfiles)", e -> manager.refreshFiles());
        JButton delete = Buttons.button("Delete", KeyEvent.VK_T, "deleteButton",
                "Delete the selected file from the server's store (?delete NAME; needs the right)", e -> confirmDelete());
        JButton clear = Buttons.button("Clear done", KeyEvent.VK_O, "clearDoneButton",
                "Remove finished transfers from the list", e -> manager.clearFinishedTransfers());
        // Two rows of buttons: one row is clipped in a quadrant of a 1280-pixel window.
        JPanel buttons = new JPanel(new GridLayout(0, 3, 4, 2));
        buttons.add(ul);
        buttons.add(dl);
        buttons.add(delete);
        buttons.add(refresh);
        buttons.add(clear);

        // Enter on a downloaded file downloads it, Delete deletes: the tree works without a mouse.
        tree.getInputMap().put(KeyStroke.getKeyStroke(KeyEvent.VK_ENTER, 0), "ripv-download");
        tree.getActionMap().put("ripv-download", action(this::chooseDownload));
        tree.getInputMap().put(KeyStroke.getKeyStroke(KeyEvent.VK_DELETE, 0), "ripv-delete");
        tree.getActionMap().put("ripv-delete", action(this::confirmDelete));
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

    private static Action action(Runnable r) {
        return new AbstractAction() {
            @Override
            public void actionPerformed(ActionEvent e) {
                r.run();
            }
        };
    }

    private void confirmDelete() {
        FileTree.File f = tree.selectedFile();
        if (f == null) {
            manager.showNotice("pick a file in the FIM tree first, then Delete", true);
            return;
        }
        int answer = JOptionPane.showConfirmDialog(this,
                "Delete " + f.entry().name() + " from the server's " + (f.area() == FileArea.UPLOAD ? "upload" : "download")
                        + " directory, for every user?", "Delete a file on the server", JOptionPane.OK_CANCEL_OPTION,
                JOptionPane.WARNING_MESSAGE);
        if (answer == JOptionPane.OK_OPTION) {
            manager.deleteFile(f.entry().name());
        }
    }

    /** The store has a file of that name: keep both, replace it, or leave it. */
    private void askAboutTakenName(Transfer t) {
        Object[] options = {"Keep both", "Replace", "Cancel"};
        int answer = JOptionPane.showOptionDialog(this,
                "The server's upload directory already has a file named " + t.name() + ".\n"
                        + "Keep both (yours is stored under a new name), replace it (needs the right), or cancel?",
                "File exists", JOptionPane.DEFAULT_OPTION, JOptionPane.QUESTION_MESSAGE, null,
                options, options[0]);
        if (answer == 0) {
            manager.upload(t.local(), ClientSocketHandler.IfExists.KEEP);
        } else if (answer == 1) {
            manager.upload(t.local(), ClientSocketHandler.IfExists.REPLACE);
        }
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
        Set<Long> seen = new HashSet<>();
        for (Transfer t : model.transfers()) {
            seen.add(t.id());
            Row r = rows.computeIfAbsent(t.id(), id -> newRow(t));
            r.bar().setIndeterminate(t.percent() < 0 && !t.finished());
            r.bar().setValue(Math.max(0, t.percent()));
            r.bar().setString(t.progressText());
            if (t.nameTaken() && isShowing() && t.claimQuestion()) {
                SwingUtilities.invokeLater(() -> askAboutTakenName(t));
            }
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
