package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.io.File;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JToggleButton;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;

/**
 * The DAta Visualization panel (thesis 4.1.3, figure 4.5): the latest plot from the
 * DataVisServer; Fit scales it to the panel, + and − zoom, 1:1 shows it at its own size, Save
 * writes the JPEG exactly as it arrived.
 */
public final class ImagePanel extends JPanel {
    private final GuiManager manager;
    private final Canvas canvas = new Canvas();
    private final JScrollPane scroll = new JScrollPane(canvas);
    private final JLabel caption = new JLabel("Send vis:FILE from the COM panel to plot an uploaded data file.");
    private final JToggleButton fit = new JToggleButton("Fit", true);
    private ServiceModel.Picture picture;
    private double zoom = 1.0;

    public ImagePanel(GuiManager manager) {
        super(new BorderLayout(4, 4));
        this.manager = manager;
        setName("dav");
        setBorder(BorderFactory.createTitledBorder("DAV — plots"));
        canvas.setName("imageCanvas");
        fit.setName("fitButton");
        fit.setMnemonic(KeyEvent.VK_F);
        fit.setToolTipText("Scale the plot to fit the panel");
        fit.addActionListener(e -> relayout());
        JButton in = new JButton("+");
        in.setToolTipText("Zoom in (Alt+=)");
        in.setMnemonic(KeyEvent.VK_EQUALS);
        in.addActionListener(e -> zoomBy(1.25));
        JButton out = new JButton("−");
        out.setToolTipText("Zoom out (Alt+-)");
        out.setMnemonic(KeyEvent.VK_MINUS);
        out.addActionListener(e -> zoomBy(0.8));
        JButton one = new JButton("1:1");
        one.setToolTipText("Actual size");
        one.addActionListener(e -> {
            zoom = 1.0;
            fit.setSelected(false);
            relayout();
        });
        JButton save = Buttons.button("Save", KeyEvent.VK_A, "saveImageButton",
                "Save the JPEG on this computer", e -> save());
        JPanel buttons = Buttons.row(fit, in, out, one, save);
        JPanel south = new JPanel(new BorderLayout());
        south.add(caption, BorderLayout.CENTER);
        south.add(buttons, BorderLayout.SOUTH);
        scroll.setPreferredSize(new Dimension(420, 260));
        scroll.addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) {
                if (fit.isSelected()) {
                    relayout();
                }
            }
        });
        add(scroll, BorderLayout.CENTER);
        add(south, BorderLayout.SOUTH);
    }

    private void zoomBy(double factor) {
        if (fit.isSelected()) {
            zoom = currentScale();
            fit.setSelected(false);
        }
        zoom = Math.max(0.05, Math.min(20, zoom * factor));
        relayout();
    }

    /** The scale the picture is drawn at now. */
    public double currentScale() {
        BufferedImage img = picture == null ? null : picture.image();
        if (img == null) {
            return 1.0;
        }
        if (!fit.isSelected()) {
            return zoom;
        }
        Dimension view = scroll.getViewport().getExtentSize();
        if (view.width <= 0 || view.height <= 0) {
            return 1.0;
        }
        return Math.min((double) view.width / img.getWidth(), (double) view.height / img.getHeight());
    }

    private void relayout() {
        canvas.revalidate();
        canvas.repaint();
    }

    private void save() {
        if (picture == null) {
            return;
        }
        JFileChooser chooser = new JFileChooser();
        chooser.setSelectedFile(new File(picture.result().name()));
        if (chooser.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            manager.save(chooser.getSelectedFile().toPath(), picture.result().jpeg().clone());
        }
    }

    /** Shows the model's latest picture; on the event thread. */
    public void update(ServiceModel m) {
        ServiceModel.Picture p = m.picture();
        if (p == picture) {
            return;
        }
        picture = p;
        if (p == null) {
            caption.setText(" ");
        } else if (p.image() == null) {
            caption.setText(p.result().name() + ": " + p.result().jpeg().length + " bytes that do not decode as an image");
        } else {
            caption.setText(p.result().name() + "  " + p.image().getWidth() + "×" + p.image().getHeight());
        }
        relayout();
    }

    /** The picture shown, or null. */
    public BufferedImage image() {
        return picture == null ? null : picture.image();
    }

    private final class Canvas extends JPanel {
        @Override
        public Dimension getPreferredSize() {
            BufferedImage img = image();
            if (img == null) {
                return new Dimension(10, 10);
            }
            if (fit.isSelected()) {
                return scroll.getViewport().getExtentSize();
            }
            return new Dimension((int) (img.getWidth() * zoom), (int) (img.getHeight() * zoom));
        }

        @Override
        protected void paintComponent(Graphics g) {
            super.paintComponent(g);
            BufferedImage img = image();
            if (img == null) {
                return;
            }
            double s = currentScale();
            int w = (int) (img.getWidth() * s);
            int h = (int) (img.getHeight() * s);
            Graphics2D g2 = (Graphics2D) g.create();
            g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g2.drawImage(img, Math.max(0, (getWidth() - w) / 2), Math.max(0, (getHeight() - h) / 2), w, h, null);
            g2.dispose();
        }
    }
}
