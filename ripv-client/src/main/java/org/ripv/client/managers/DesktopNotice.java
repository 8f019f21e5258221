package org.ripv.client.managers;

import java.awt.AWTException;
import java.awt.GraphicsEnvironment;
import java.awt.SystemTray;
import java.awt.TrayIcon;
import java.awt.image.BufferedImage;
import java.util.function.BiConsumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A desktop notification for SURFACED and ALERT: a tray balloon where the desktop has a system
 * tray, else the window's own notice (status bar) so nothing is lost on desktops without one.
 */
final class DesktopNotice {
    private static final Logger log = LoggerFactory.getLogger(DesktopNotice.class);
    private final BiConsumer<String, Boolean> inWindow;
    private TrayIcon icon;
    private boolean trayTried;

    DesktopNotice(BiConsumer<String, Boolean> inWindow) {
        this.inWindow = inWindow;
    }

    /** Shows it; call on the UI thread. */
    void show(String title, String text, boolean alert) {
        inWindow.accept(title + ": " + text, alert);
        TrayIcon t = tray();
        if (t != null) {
            t.displayMessage(title, text, alert ? TrayIcon.MessageType.WARNING : TrayIcon.MessageType.INFO);
        }
    }

    private TrayIcon tray() {
        if (trayTried) {
            return icon;
        }
        trayTried = true;
        if (GraphicsEnvironment.isHeadless() || !SystemTray.isSupported()) {
            return null;
        }
        try {
            TrayIcon t = new TrayIcon(new BufferedImage(16, 16, BufferedImage.TYPE_INT_ARGB), "RIPV");
            t.setImageAutoSize(true);
            SystemTray.getSystemTray().add(t);
            icon = t;
        } catch (AWTException | RuntimeException e) {
            log.debug("no system tray: {}", e.toString());
        }
        return icon;
    }
}
