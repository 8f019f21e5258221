package org.ripv.client.fleet;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Component;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import javax.swing.JComponent;
import javax.swing.JTable;
import javax.swing.UIManager;
import javax.swing.table.TableCellRenderer;

/**
 * A vehicle's small track in a table cell: the recent fixes as a line at the aspect right for
 * the latitude (north up), the newest fix as a red dot.
 */
final class TrackCell extends JComponent implements TableCellRenderer {
    private FleetModel.Vehicle vehicle;
    private boolean selected;

    @Override
    public Component getTableCellRendererComponent(JTable table, Object value, boolean isSelected, boolean hasFocus, int row,
                                                   int column) {
        vehicle = value instanceof FleetModel.Vehicle v ? v : null;
        selected = isSelected;
        setBackground(isSelected ? table.getSelectionBackground() : table.getBackground());
        setForeground(isSelected ? table.getSelectionForeground() : table.getForeground());
        return this;
    }

    @Override
    protected void paintComponent(Graphics g) {
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            g2.setColor(getBackground());
            g2.fillRect(0, 0, getWidth(), getHeight());
            g2.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            paintTrack(g2, vehicle, 8, 7, getWidth() - 16, getHeight() - 14,
                    selected ? getForeground() : UIManager.getColor("Component.accentColor") == null ? new Color(0x2f6fb3)
                            : UIManager.getColor("Component.accentColor"));
        } finally {
            g2.dispose();
        }
    }

    /** Draws the track in the box; also used by tests and the screenshots. */
    static void paintTrack(Graphics2D g, FleetModel.Vehicle v, double x0, double y0, double w, double h, Color line) {
        if (v == null || w <= 0 || h <= 0) {
            return;
        }
        double[] lon = v.trackLon() == null ? new double[0] : v.trackLon();
        double[] lat = v.trackLat() == null ? new double[0] : v.trackLat();
        double minX = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < lon.length; i++) {
            minX = Math.min(minX, lon[i]);
            maxX = Math.max(maxX, lon[i]);
            minY = Math.min(minY, lat[i]);
            maxY = Math.max(maxY, lat[i]);
        }
        if (v.hasFix()) {
            minX = Math.min(minX, v.lon());
            maxX = Math.max(maxX, v.lon());
            minY = Math.min(minY, v.lat());
            maxY = Math.max(maxY, v.lat());
        }
        if (minX > maxX) {
            return;
        }
        double k = Math.max(0.01, Math.cos(Math.toRadians((minY + maxY) / 2)));
        double spanX = Math.max((maxX - minX) * k, 1e-5);
        double spanY = Math.max(maxY - minY, 1e-5);
        double scale = Math.min(w / spanX, h / spanY);
        double cx = x0 + w / 2;
        double cy = y0 + h / 2;
        double mx = (minX + maxX) / 2;
        double my = (minY + maxY) / 2;
        Path2D.Double path = new Path2D.Double();
        for (int i = 0; i < lon.length; i++) {
            double px = cx + (lon[i] - mx) * k * scale;
            double py = cy - (lat[i] - my) * scale;
            if (i == 0) {
                path.moveTo(px, py);
            } else {
                path.lineTo(px, py);
            }
        }
        g.setColor(line);
        g.setStroke(new BasicStroke(1.3f));
        g.draw(path);
        if (v.hasFix()) {
            double px = cx + (v.lon() - mx) * k * scale;
            double py = cy - (v.lat() - my) * scale;
            g.setColor(Color.RED);
            g.fill(new Ellipse2D.Double(px - 3.5, py - 3.5, 7, 7));
        }
    }
}
