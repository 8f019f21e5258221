package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.DefaultListModel;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import javax.swing.ListSelectionModel;
import javax.swing.SwingUtilities;
import javax.swing.UIManager;
import org.ripv.client.handlers.ClientSocketHandler.IfExists;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ConsoleModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.WorkflowModel;

/**
 * One vehicle MailBox's workflow queue and receipts (docs/workflows.md), opened from the MAM
 * panel: the queue as {@code ?queue} lists it, with Add file…, Remove and Clear; a small editor
 * to write a workflow and queue it (it is uploaded, then {@code ?queue add}), where a refused
 * file's line is marked and its reason listed; the receipts ({@code ?receipts}); and the
 * workflow lines and WORKFLOW_DONE / WORKFLOW_FAILED events of the live console. It renders
 * {@link WorkflowModel}; the queue is asked again whenever a workflow event arrives.
 */
public final class WorkflowDialog extends JDialog {
    /** What the editor starts with: the file format in a few lines. */
    static final String EXAMPLE = """
            # One step a line; '#' starts a comment. docs/workflows.md has them all.
            workflow once
            send dir expect='\\.MI|\\.LOG|\\.DBD|\\.SBD' timeout=30s
            ymodem:get *.SBD timeout=10m
            notify "logs fetched"
            """;

    private final GuiManager manager;
    private final ClientModel model;
    private final String mailbox;
    private final WorkflowQueueTable table = new WorkflowQueueTable();
    private final JTable queueTable = new JTable(table);
    private final JLabel outcome = new JLabel(" ");
    private final DefaultListModel<WorkflowModel.Refusal> refusals = new DefaultListModel<>();
    private final JList<WorkflowModel.Refusal> refusalList = new JList<>(refusals);
    private final WorkflowEditor editor;
    private final ReceiptsTab receipts = new ReceiptsTab(this::refresh);
    private final WorkflowEvents events = new WorkflowEvents();
    private final JTabbedPane tabs = new JTabbedPane();
    private JScrollPane refusalScroll;
    private final WorkflowModel.Listener queueListener;
    private final ConsoleModel.Listener consoleListener;
    /** What "Keep both" or "Replace" does after the server said the name is taken. */
    private Consumer<IfExists> retry;
    /** The file Add file… sent last: a refused one is opened in the editor, at the line at fault. */
    private Path sentFile;
    /** Names this window uploaded: sending one again (a mended workflow) replaces it without asking. */
    private final Set<String> uploadedHere = new HashSet<>();

    public WorkflowDialog(Window owner, GuiManager manager, String mailbox) {
        super(owner, "Workflows — " + handle(mailbox), ModalityType.MODELESS);
        this.manager = manager;
        this.model = manager.model();
        this.mailbox = mailbox;
        this.editor = new WorkflowEditor(handle(mailbox) + ".wf", () -> queueText(IfExists.ASK));
        setName("workflowDialog");
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);

        JLabel title = new JLabel(mailbox);
        title.setName("workflowMailbox");
        title.setBorder(BorderFactory.createEmptyBorder(4, 6, 4, 6));
        title.setFont(title.getFont().deriveFont(Font.BOLD));

        tabs.setName("workflowTabs");
        tabs.addTab("Queue", queueTab());
        tabs.setMnemonicAt(0, KeyEvent.VK_Q);
        tabs.addTab("Write a workflow", editor);
        tabs.setMnemonicAt(1, KeyEvent.VK_W);
        tabs.addTab("Receipts", receipts);
        tabs.setMnemonicAt(2, KeyEvent.VK_R);

        outcome.setName("workflowOutcome");
        refusalList.setName("workflowRefusals");
        refusalList.setVisibleRowCount(2);
        refusalList.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        refusalList.addListSelectionListener(e -> {
            WorkflowModel.Refusal r = refusalList.getSelectedValue();
            if (!e.getValueIsAdjusting() && r != null && r.line() > 0) {
                tabs.setSelectedIndex(1);
                editor.markLine(r.line());
            }
        });
        JPanel south = new JPanel(new BorderLayout(4, 2));
        south.setBorder(BorderFactory.createEmptyBorder(2, 6, 6, 6));
        south.add(outcome, BorderLayout.NORTH);
        refusalScroll = new JScrollPane(refusalList);
        refusalScroll.setBorder(BorderFactory.createTitledBorder("Refused: the line and why (click to show it in the editor)"));
        south.add(refusalScroll, BorderLayout.CENTER);

        getContentPane().add(title, BorderLayout.NORTH);
        getContentPane().add(tabs, BorderLayout.CENTER);
        getContentPane().add(south, BorderLayout.SOUTH);
        setPreferredSize(new Dimension(900, 620));
        pack();
        setLocationRelativeTo(owner);

        queueListener = changed -> {
            if (changed.equals(mailbox)) {
                render();
            }
        };
        consoleListener = changed -> {
            if (changed.equals(mailbox) && events.show(model.console().entries(mailbox))) {
                refresh(); // a new workflow line or event: the queue has moved on
            }
        };
        model.workflows().addListener(queueListener);
        model.console().addListener(consoleListener);
        render();
        events.show(model.console().entries(mailbox));
        refresh();
        SwingUtilities.invokeLater(receipts::split);
    }

    private static String handle(String address) {
        int i = address.lastIndexOf('>');
        return i < 0 ? address : address.substring(i + 1);
    }

    private JPanel queueTab() {
        queueTable.setName("queueTable");
        queueTable.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        queueTable.setAutoResizeMode(JTable.AUTO_RESIZE_LAST_COLUMN);
        int[] widths = {40, 80, 80, 170, 50, 330};
        for (int i = 0; i < widths.length; i++) {
            queueTable.getColumnModel().getColumn(i).setPreferredWidth(widths[i]);
        }
        JPanel buttons = Buttons.row(
                Buttons.button("Refresh", KeyEvent.VK_F, "queueRefresh", "Ask the server again (?queue, ?receipts)",
                        e -> refresh()),
                Buttons.button("Add file…", KeyEvent.VK_A, "queueAddFile",
                        "Upload a workflow file from this computer and queue it (?queue add)", e -> chooseFile()),
                Buttons.button("Remove", KeyEvent.VK_M, "queueRemove", "Remove the selected workflow (?queue remove)",
                        e -> removeSelected()),
                Buttons.button("Clear", KeyEvent.VK_L, "queueClear", "Remove every workflow of this MailBox (?queue clear)",
                        e -> clearAsked()));

        JSplitPane split = new JSplitPane(JSplitPane.VERTICAL_SPLIT, new JScrollPane(queueTable), events);
        split.setResizeWeight(0.6);
        split.setBorder(null);
        JPanel p = new JPanel(new BorderLayout(4, 4));
        lay(p, split, buttons, BorderLayout.SOUTH);
        return p;
    }

    private void clearAsked() {
        if (JOptionPane.showConfirmDialog(this, "Remove every workflow queued for " + handle(mailbox) + "?",
                "Clear the queue", JOptionPane.OK_CANCEL_OPTION, JOptionPane.WARNING_MESSAGE) == JOptionPane.OK_OPTION) {
            manager.clearQueue(mailbox);
        }
    }

    /** The layout the dialog's tabs share: {@code content} in the middle, a bar of controls at {@code edge}, 4 px around. */
    static void lay(JPanel tab, Component content, JComponent bar, String edge) {
        tab.setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        tab.add(content, BorderLayout.CENTER);
        tab.add(bar, edge);
    }

    /** A row: a label with its mnemonic, the field it names, and a button. */
    static JPanel row(String label, int mnemonic, JComponent field, JButton button) {
        JLabel l = new JLabel(label);
        l.setDisplayedMnemonic(mnemonic);
        l.setLabelFor(field);
        return Buttons.row(l, field, button);
    }

    /** Asks the server for the queue and the receipts. */
    public void refresh() {
        manager.refreshQueue(mailbox, receipts.last());
    }

    private void chooseFile() {
        JFileChooser chooser = new JFileChooser();
        chooser.setDialogTitle("Queue a workflow file for " + handle(mailbox));
        if (chooser.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) {
            queueFile(chooser.getSelectedFile().toPath(), IfExists.ASK);
        }
    }

    /** Uploads a workflow file and queues it (what Add file… does once a file is chosen). */
    public void queueFile(Path file, IfExists ifExists) {
        retry = how -> queueFile(file, how);
        sentFile = file;
        outcome("uploading " + file.getFileName() + " …", false);
        manager.queueFile(mailbox, file, ifExists);
    }

    private void queueText(IfExists ifExists) {
        String n = editor.fileName();
        if (n.isEmpty()) {
            outcome("give the workflow a name first (e.g. " + handle(mailbox) + ".wf)", true);
            return;
        }
        String text = editor.text();
        sentFile = null;
        retry = how -> {
            outcome("uploading " + n + " …", false);
            uploadedHere.add(n);
            manager.queueText(mailbox, n, text, how);
        };
        retry.accept(ifExists == IfExists.ASK && uploadedHere.contains(n) ? IfExists.REPLACE : ifExists);
    }

    private void removeSelected() {
        int row = queueTable.getSelectedRow();
        if (row < 0) {
            outcome("pick a workflow in the queue first, then Remove", true);
            return;
        }
        manager.unqueue(mailbox, table.entry(row).id());
    }

    private void outcome(String text, boolean error) {
        String first = text.lines().findFirst().orElse(" ");
        outcome.setText(first.isBlank() ? " " : first);
        outcome.setToolTipText(text.isBlank() ? null : text);
        outcome.setForeground(error ? Colors.error() : UIManager.getColor("Label.foreground"));
    }

    private void render() {
        WorkflowModel.Queue q = model.workflows().queue(mailbox);
        long selected = queueTable.getSelectedRow() < 0 ? -1 : table.entry(queueTable.getSelectedRow()).id();
        table.show(q.entries());
        for (int i = 0; i < q.entries().size(); i++) {
            if (q.entries().get(i).id() == selected) {
                queueTable.setRowSelectionInterval(i, i);
            }
        }
        if (!q.outcome().isEmpty()) {
            outcome(q.outcome(), q.outcomeIsError());
        }
        refusals.clear();
        q.refusals().forEach(refusals::addElement);
        if (refusalScroll.isVisible() == q.refusals().isEmpty()) {
            refusalScroll.setVisible(!q.refusals().isEmpty()); // only when there is something to show
            getContentPane().revalidate();
        }
        editor.clearMark();
        if (!q.refusals().isEmpty() && sentFile != null) {
            // A refused file from disk: open it in the editor to mend it there.
            try {
                editorText(sentFile.getFileName().toString(), Files.readString(sentFile));
                tabs.setSelectedIndex(1);
            } catch (IOException | RuntimeException e) {
                outcome(q.outcome() + " (and " + sentFile + " cannot be read again: " + e.getMessage() + ")", true);
            }
            sentFile = null;
        }
        if (!q.refusals().isEmpty() && q.refusals().get(0).line() > 0 && tabs.getSelectedIndex() == 1) {
            editor.markLine(q.refusals().get(0).line());
        }
        receipts.show(q.receipts());
        if (!q.nameTaken().isEmpty() && retry != null && isShowing()) {
            Consumer<IfExists> again = retry;
            retry = null;
            SwingUtilities.invokeLater(() -> askAboutTakenName(q.nameTaken(), again));
        }
    }

    private void askAboutTakenName(String taken, Consumer<IfExists> again) {
        Object[] options = {"Keep both", "Replace", "Cancel"};
        int answer = JOptionPane.showOptionDialog(this, "The server's upload directory already has a file named " + taken + ".\n"
                        + "Keep both (yours is stored under a new name and that one is queued), replace it (needs the right), or cancel?",
                "File exists", JOptionPane.DEFAULT_OPTION, JOptionPane.QUESTION_MESSAGE, null, options, options[0]);
        if (answer == 0) {
            again.accept(IfExists.KEEP);
        } else if (answer == 1) {
            again.accept(IfExists.REPLACE);
        }
    }

    /** Shows one tab: 0 queue, 1 editor, 2 receipts. */
    public void showTab(int index) {
        tabs.setSelectedIndex(index);
    }

    /** Puts text into the editor (tests, and a future "open"). */
    public void editorText(String name, String text) {
        editor.show(name, text);
    }

    /** The editor's name and text, as "NAME\nTEXT". */
    public String editorContent() {
        return editor.content();
    }

    /** Queues what the editor holds, as "Upload and queue" does. */
    public void queueEditorText() {
        queueText(IfExists.ASK);
    }

    public String mailbox() {
        return mailbox;
    }

    public String outcomeText() {
        return outcome.getText();
    }

    public List<String> refusalTexts() {
        return Collections.list(refusals.elements()).stream().map(Object::toString).toList();
    }

    /** The editor line marked as refused (1-based), or 0. */
    public int markedLine() {
        return editor.markedLine();
    }

    public String eventsText() {
        return events.text();
    }

    public List<String> receiptTitles() {
        return receipts.titles();
    }

    public int queueRows() {
        return table.getRowCount();
    }

    @Override
    public void dispose() {
        model.workflows().removeListener(queueListener);
        model.console().removeListener(consoleListener);
        super.dispose();
    }
}
