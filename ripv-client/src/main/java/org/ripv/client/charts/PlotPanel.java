package org.ripv.client.charts;

import java.awt.BorderLayout;
import java.awt.CardLayout;
import java.awt.Component;
import java.awt.Point;
import java.awt.event.ActionEvent;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.KeyEvent;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;
import javax.swing.AbstractAction;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JPanel;
import javax.swing.JPopupMenu;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import org.jfree.chart.ChartMouseEvent;
import org.jfree.chart.ChartMouseListener;
import org.jfree.chart.ChartPanel;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.plot.XYPlot;
import org.jfree.data.Range;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;
import org.ripv.client.panels.Buttons;
import org.ripv.client.panels.ImagePanel;
import org.ripv.export.ChartExport;
import org.ripv.messages.ChartData;

/**
 * The DAV quadrant: the latest plot as an interactive chart when the reply carried its data
 * (the built-in worker), else the JPEG in an {@link ImagePanel} as before (Octave, MATLAB).
 *
 * <p>On the chart: drag a rectangle or turn the mouse wheel to zoom, Ctrl+drag to pan (also the
 * arrow keys, + and − when the chart has the focus; 0 resets), the point nearest the cursor is
 * described under the chart; <b>Reset zoom</b> (Alt+Z) and <b>Save as…</b> (Alt+A): the chart as
 * PNG or SVG, its data as CSV or JSON, or the JPEG as it arrived.
 */
public final class PlotPanel extends JPanel {
    /** What {@link #export} writes. */
    public enum Format { PNG, SVG, CSV, JSON, JPEG }

    private static final int MAX_PIXELS = 12;
    private final GuiManager manager;
    private final CardLayout cards = new CardLayout();
    private final ImagePanel image;
    private final ChartPanel chartPanel = new ChartPanel(null, 560, 320, 200, 120, 4000, 4000, true, true, true, true,
            true, true);
    private final JLabel readout = new JLabel(" ");
    private final JLabel caption = new JLabel(" ");
    private ServiceModel.Picture picture;
    private ChartData data;
    private JFreeChart chart;

    public PlotPanel(GuiManager manager) {
        super();
        setLayout(cards);
        this.manager = manager;
        setName("plotPanel");
        image = new ImagePanel(manager);
        chartPanel.setName("chartPanel");
        chartPanel.setMouseWheelEnabled(true);
        chartPanel.setFocusable(true);
        chartPanel.setDisplayToolTips(true);
        chartPanel.setInitialDelay(200);
        chartPanel.addChartMouseListener(new ChartMouseListener() {
            @Override
            public void chartMouseClicked(ChartMouseEvent event) {
                chartPanel.requestFocusInWindow();
            }

            @Override
            public void chartMouseMoved(ChartMouseEvent event) {
                Readout r = readoutAt(event.getTrigger().getPoint());
                readout.setText(r == null ? " " : r.text());
            }
        });
        keys();
        readout.setName("chartReadout");
        caption.setName("chartCaption");

        JButton reset = Buttons.button("Reset zoom", KeyEvent.VK_Z, "resetZoomButton",
                "Show all the data again (0 on the chart)", e -> resetZoom());
        JButton save = Buttons.button("Save as…", KeyEvent.VK_A, "saveChartButton",
                "The chart as PNG or SVG, its data as CSV or JSON, or the JPEG as it arrived");
        JPopupMenu formats = new JPopupMenu();
        for (Format f : Format.values()) {
            JMenuItem item = new JMenuItem(switch (f) {
                case PNG -> "PNG picture…";
                case SVG -> "SVG picture…";
                case CSV -> "Data as CSV…";
                case JSON -> "Data as JSON…";
                case JPEG -> "JPEG as received…";
            });
            item.setName("save-" + f.name().toLowerCase(Locale.ROOT));
            item.setMnemonic(f.name().charAt(0));
            item.addActionListener(e -> choose(f));
            formats.add(item);
        }
        save.addActionListener(e -> formats.show(save, 0, save.getHeight()));
        svgInChartMenu();
        JPanel buttons = Buttons.row(reset, save, caption);
        JPanel south = new JPanel(new BorderLayout());
        south.add(readout, BorderLayout.NORTH);
        south.add(buttons, BorderLayout.SOUTH);
        JPanel chartCard = new JPanel(new BorderLayout(4, 4));
        chartCard.setName("dav-chart");
        chartCard.setBorder(BorderFactory.createTitledBorder("DAV — plots"));
        chartCard.add(chartPanel, BorderLayout.CENTER);
        chartCard.add(south, BorderLayout.SOUTH);
        add(image, "image");
        add(chartCard, "chart");
        cards.show(this, "image");
        chartPanel.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                if (chart != null && data.kind() == ChartData.Kind.TRACK && isAutoRange()) {
                    fitTrack();
                }
            }
        });
    }

    private boolean trackZoomed;

    /** JFreeChart's right-click "Save as" offers SVG only with JFreeSVG (GPL, not shipped): offer ours there. */
    private void svgInChartMenu() {
        JPopupMenu menu = chartPanel.getPopupMenu();
        for (Component c : menu == null ? new Component[0] : menu.getComponents()) {
            if (c instanceof JMenu sub) {
                for (Component i : sub.getMenuComponents()) {
                    if (i instanceof JMenuItem png && "SAVE_AS_PNG".equals(png.getActionCommand())) {
                        JMenuItem svg = new JMenuItem("SVG...");
                        svg.setName("chartMenu-svg");
                        svg.addActionListener(e -> choose(Format.SVG));
                        sub.add(svg);
                        return;
                    }
                }
            }
        }
    }

    private boolean isAutoRange() {
        return !trackZoomed;
    }

    private void keys() {
        bind("LEFT", "panLeft", () -> pan(-0.1, 0));
        bind("RIGHT", "panRight", () -> pan(0.1, 0));
        bind("UP", "panUp", () -> pan(0, 0.1));
        bind("DOWN", "panDown", () -> pan(0, -0.1));
        bind("PLUS", "zoomIn", () -> zoom(0.8));
        bind("EQUALS", "zoomIn", () -> zoom(0.8));
        bind("ADD", "zoomIn", () -> zoom(0.8));
        bind("MINUS", "zoomOut", () -> zoom(1.25));
        bind("SUBTRACT", "zoomOut", () -> zoom(1.25));
        bind("0", "resetZoom", this::resetZoom);
    }

    private void bind(String key, String name, Runnable r) {
        chartPanel.getInputMap(JComponent.WHEN_FOCUSED).put(KeyStroke.getKeyStroke(key), name);
        chartPanel.getActionMap().put(name, new AbstractAction(name) {
            @Override
            public void actionPerformed(ActionEvent e) {
                r.run();
            }
        });
    }

    /** Moves the view by a fraction of its span (positive: right, up). */
    public void pan(double fx, double fy) {
        if (chart == null) {
            return;
        }
        XYPlot plot = chart.getXYPlot();
        trackZoomed = true;
        if (fx != 0) {
            Range r = plot.getDomainAxis().getRange();
            plot.getDomainAxis().setRange(r.getLowerBound() + fx * r.getLength(), r.getUpperBound() + fx * r.getLength());
        }
        if (fy != 0) {
            double f = plot.getRangeAxis().isInverted() ? -fy : fy;
            Range r = plot.getRangeAxis().getRange();
            plot.getRangeAxis().setRange(r.getLowerBound() + f * r.getLength(), r.getUpperBound() + f * r.getLength());
        }
    }

    /** Zooms about the centre: {@code factor} below 1 zooms in. */
    public void zoom(double factor) {
        if (chart == null) {
            return;
        }
        trackZoomed = true;
        chart.getXYPlot().getDomainAxis().resizeRange(factor);
        chart.getXYPlot().getRangeAxis().resizeRange(factor);
    }

    /** All the data again (a track at its right aspect). */
    public void resetZoom() {
        if (chart == null) {
            return;
        }
        trackZoomed = false;
        if (data.kind() == ChartData.Kind.TRACK) {
            fitTrack();
        } else {
            chartPanel.restoreAutoBounds();
        }
    }

    private void fitTrack() {
        Rectangle2D area = chartPanel.getScreenDataArea();
        double w = area.getWidth() > 10 ? area.getWidth() : Math.max(100, chartPanel.getWidth() - 110);
        double h = area.getHeight() > 10 ? area.getHeight() : Math.max(100, chartPanel.getHeight() - 110);
        Charts.fit(chart, data, w, h);
    }

    /** The point nearest to a point of the chart panel (its own coordinates), or null. */
    public Readout readoutAt(Point p) {
        if (chart == null) {
            return null;
        }
        Rectangle2D area = chartPanel.getScreenDataArea();
        if (area.getWidth() <= 0 || area.getHeight() <= 0 || !area.contains(p)) {
            return null;
        }
        XYPlot plot = chart.getXYPlot();
        double x = plot.getDomainAxis().java2DToValue(p.getX(), area, plot.getDomainAxisEdge());
        double y = plot.getRangeAxis().java2DToValue(p.getY(), area, plot.getRangeAxisEdge());
        double xPerPixel = plot.getDomainAxis().getRange().getLength() / area.getWidth();
        double yPerPixel = plot.getRangeAxis().getRange().getLength() / area.getHeight();
        return Readout.nearest(data, x, y, xPerPixel, yPerPixel, MAX_PIXELS);
    }

    /** Where a data point is drawn, in the chart panel's coordinates (tests move the mouse there). */
    public Point2D screenPoint(double x, double y) {
        Rectangle2D area = chartPanel.getScreenDataArea();
        XYPlot plot = chart.getXYPlot();
        return new Point2D.Double(plot.getDomainAxis().valueToJava2D(x, area, plot.getDomainAxisEdge()),
                plot.getRangeAxis().valueToJava2D(y, area, plot.getRangeAxisEdge()));
    }

    private void choose(Format f) {
        if (picture == null || (data == null && f != Format.JPEG)) {
            return;
        }
        String base = picture.result().name().replaceFirst("(?i)\\.jpe?g$", "");
        JFileChooser chooser = new JFileChooser();
        chooser.setSelectedFile(new File(base + "." + (f == Format.JPEG ? "jpg" : f.name().toLowerCase(Locale.ROOT))));
        if (chooser.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            export(f, chooser.getSelectedFile().toPath());
        }
    }

    /**
     * Writes the chart (PNG, SVG: as the panel shows it now, zoom included, at its size), its data
     * (CSV, JSON: every point received) or the JPEG as it arrived; the file is written off the
     * event thread and the outcome is a notice in the status bar.
     */
    public void export(Format f, Path file) {
        try {
            manager.save(file, bytes(f));
        } catch (IOException | RuntimeException e) {
            manager.showNotice("could not write " + file + ": " + e.getMessage(), true);
        }
    }

    /** What {@link #export} writes for a format. */
    public byte[] bytes(Format f) throws IOException {
        if (f == Format.JPEG) {
            return picture.result().jpeg().clone();
        }
        int w = Math.max(400, chartPanel.getWidth());
        int h = Math.max(300, chartPanel.getHeight());
        return switch (f) {
            case PNG -> Charts.png(chart, w, h);
            case SVG -> Charts.svg(chart, w, h);
            case CSV -> ChartExport.csv(data).getBytes(StandardCharsets.UTF_8);
            case JSON -> ChartExport.json(data).getBytes(StandardCharsets.UTF_8);
            case JPEG -> throw new IllegalStateException();
        };
    }

    /** Shows the model's latest plot; on the event thread. */
    public void update(ServiceModel m) {
        image.update(m);
        ServiceModel.Picture p = m.picture();
        if (p == picture) {
            return;
        }
        picture = p;
        data = p == null ? null : p.result().chart();
        if (data == null) {
            chart = null;
            chartPanel.setChart(null);
            cards.show(this, "image");
            return;
        }
        chart = Charts.chart(data);
        chartPanel.setChart(chart);
        trackZoomed = false;
        readout.setText(" ");
        caption.setText(p.result().name() + "  " + data.points() + " points"
                + (data.reduced() ? " of " + data.rows() + " rows (reduced)" : ""));
        cards.show(this, "chart");
        if (data.kind() == ChartData.Kind.TRACK) {
            SwingUtilities.invokeLater(this::fitTrack); // once the panel knows its data area
        }
    }

    /** The JPEG view (shown when a plot came without data). */
    public ImagePanel image() {
        return image;
    }

    /** The chart view. */
    public ChartPanel chartPanel() {
        return chartPanel;
    }

    /** The chart shown, or null when the JPEG is. */
    public JFreeChart chart() {
        return chart;
    }

    /** The data of the chart shown, or null. */
    public ChartData data() {
        return data;
    }

    /** Whether the interactive chart (rather than the JPEG) is showing. */
    public boolean showsChart() {
        return chart != null;
    }

    /** The text under the chart: the point under the cursor. */
    public String readoutText() {
        return readout.getText();
    }
}
