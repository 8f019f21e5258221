package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Font;
import java.awt.event.KeyEvent;
import javax.swing.BorderFactory;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.UIManager;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.text.BadLocationException;
import javax.swing.text.DefaultHighlighter;
import javax.swing.text.Highlighter;

/**
 * The workflow dialog's "Write a workflow" tab: a name, the text with line numbers, and "Upload
 * and queue". A line the server refused is marked until the next refusal check or edit.
 */
final class WorkflowEditor extends JPanel {
    private final JTextField name = new JTextField(18);
    private final JTextArea editor = new JTextArea(WorkflowDialog.EXAMPLE);
    private final JTextArea lineNumbers = new JTextArea("1");
    private Object highlight;

    /** @param queue what "Upload and queue" does */
    WorkflowEditor(String defaultName, Runnable queue) {
        super(new BorderLayout(4, 4));
        name.setName("workflowName");
        name.setText(defaultName);
        name.setToolTipText("The name the workflow is uploaded under (the server's upload directory)");
        editor.setName("workflowEditor");
        Font mono = new Font(Font.MONOSPACED, Font.PLAIN, editor.getFont().getSize());
        editor.setFont(mono);
        editor.setTabSize(4);
        lineNumbers.setFont(mono);
        lineNumbers.setEditable(false);
        lineNumbers.setFocusable(false);
        lineNumbers.setBackground(UIManager.getColor("Panel.background"));
        lineNumbers.setBorder(BorderFactory.createEmptyBorder(0, 4, 0, 6));
        editor.getDocument().addDocumentListener(new DocumentListener() {
            @Override
            public void insertUpdate(DocumentEvent e) {
                edited();
            }

            @Override
            public void removeUpdate(DocumentEvent e) {
                edited();
            }

            @Override
            public void changedUpdate(DocumentEvent e) {
                edited();
            }
        });
        edited();
        JScrollPane scroll = new JScrollPane(editor);
        scroll.setRowHeaderView(lineNumbers);
        JPanel top = WorkflowDialog.row("Name:", KeyEvent.VK_N, name, Buttons.button("Upload and queue", KeyEvent.VK_U,
                "queueText", "Upload the text as NAME and queue it for this MailBox (?upload, then ?queue add)", e -> queue.run()));
        WorkflowDialog.lay(this, scroll, top, BorderLayout.NORTH);
    }

    String fileName() {
        return name.getText().strip();
    }

    String text() {
        return editor.getText();
    }

    void show(String fileName, String text) {
        name.setText(fileName);
        editor.setText(text);
        editor.setCaretPosition(0);
    }

    /** The name and text, as "NAME\nTEXT". */
    String content() {
        return name.getText() + "\n" + editor.getText();
    }

    /** The line numbers follow the text. */
    private void edited() {
        int lines = editor.getLineCount();
        StringBuilder b = new StringBuilder();
        for (int i = 1; i <= lines; i++) {
            b.append(i).append(i < lines ? "\n" : "");
        }
        if (!b.toString().equals(lineNumbers.getText())) {
            lineNumbers.setText(b.toString());
        }
    }

    /** Marks a refused line (1-based; past the end marks the last) and puts the caret there. */
    void markLine(int line) {
        clearMark();
        try {
            int start = editor.getLineStartOffset(Math.min(line, editor.getLineCount()) - 1);
            int end = editor.getLineEndOffset(Math.min(line, editor.getLineCount()) - 1);
            Color c = Colors.dark() ? new Color(0x6B2A2A) : new Color(0xFFD6D6);
            highlight = editor.getHighlighter().addHighlight(start, end, new DefaultHighlighter.DefaultHighlightPainter(c));
            editor.setCaretPosition(start);
        } catch (BadLocationException e) {
            highlight = null;
        }
    }

    void clearMark() {
        if (highlight != null) {
            editor.getHighlighter().removeHighlight(highlight);
            highlight = null;
        }
    }

    /** The marked line (1-based), or 0. */
    int markedLine() {
        if (highlight == null) {
            return 0;
        }
        try {
            return editor.getLineOfOffset(((Highlighter.Highlight) highlight).getStartOffset()) + 1;
        } catch (BadLocationException e) {
            return 0;
        }
    }
}
