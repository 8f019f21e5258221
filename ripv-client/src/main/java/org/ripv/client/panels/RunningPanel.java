package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.Timer;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;

/**
 * The COM panel's requests in flight: one progress bar per request of this tab still waiting
 * for its final reply — a transfer with bytes, rate and time left, a query, a plot or a vehicle
 * command with the time it has run — each with a Cancel button that sends
 * {@code ?cancel MESSAGE-ID}.
 */
final class RunningPanel extends JPanel {
    private final String service;
    private final GuiManager manager;
    private final Map<Long, Row> rows = new LinkedHashMap<>();
    private final Timer clock;
    private List<ServiceModel.Running> shown = List.of();

    private record Row(JPanel panel, JProgressBar bar, JButton cancel) {}

    RunningPanel(String service, GuiManager manager) {
        this.service = service;
        this.manager = manager;
        setName("running");
        setLayout(new BoxLayout(this, BoxLayout.Y_AXIS));
        // The running time moves on between replies.
        clock = new Timer(1000, e -> refreshTexts());
        clock.setRepeats(true);
    }

    /** Shows the tab's running requests; on the event thread. */
    void update(ServiceModel m) {
        shown = m.running();
        Set<Long> seen = new HashSet<>();
        for (ServiceModel.Running r : shown) {
            seen.add(r.messageId());
            Row row = rows.computeIfAbsent(r.messageId(), id -> newRow(id, r.command()));
            row.bar().setIndeterminate(r.progress() == null || r.progress().percent() < 0);
            row.bar().setValue(r.progress() == null ? 0 : Math.max(0, r.progress().percent()));
            row.cancel().setEnabled(!r.cancelling());
            row.cancel().setText(r.cancelling() ? "Cancelling…" : "Cancel");
        }
        rows.entrySet().removeIf(e -> {
            if (!seen.contains(e.getKey())) {
                remove(e.getValue().panel());
                return true;
            }
            return false;
        });
        refreshTexts();
        if (rows.isEmpty()) {
            clock.stop();
        } else if (!clock.isRunning()) {
            clock.start();
        }
        setVisible(!rows.isEmpty());
        revalidate();
        repaint();
    }

    private void refreshTexts() {
        long now = System.currentTimeMillis();
        for (ServiceModel.Running r : shown) {
            Row row = rows.get(r.messageId());
            if (row != null) {
                String text = r.text(now);
                row.bar().setString(text);
                row.bar().setToolTipText("#" + r.messageId() + " " + r.command() + " — " + text);
            }
        }
    }

    private Row newRow(long id, String command) {
        JPanel p = new JPanel(new BorderLayout(4, 0));
        JProgressBar bar = new JProgressBar(0, 100);
        bar.setName("running-" + id);
        bar.setStringPainted(true);
        JButton cancel = new JButton("Cancel");
        cancel.setName("cancel-" + id);
        cancel.setToolTipText("Stop '" + command + "' on the server (?cancel " + id + ")");
        cancel.addActionListener(e -> manager.cancel(service, id));
        p.add(bar, BorderLayout.CENTER);
        p.add(cancel, BorderLayout.EAST);
        p.setBorder(BorderFactory.createEmptyBorder(1, 0, 1, 0));
        add(p);
        return new Row(p, bar, cancel);
    }

    /** The progress bars' words, oldest first (tests). */
    List<String> texts() {
        return rows.values().stream().map(r -> r.bar().getString()).toList();
    }

    @Override
    public void removeNotify() {
        clock.stop();
        super.removeNotify();
    }
}
