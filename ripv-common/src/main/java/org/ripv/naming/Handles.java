package org.ripv.naming;

import java.net.InetAddress;
import java.net.URI;
import java.net.UnknownHostException;
import java.nio.file.Path;
import java.util.Locale;

/** How MailBox handles are chosen (SPEC §3), and the name this host goes by. */
public final class Handles {
    private Handles() {}

    /** The handle of a service with one static resource: COM1 on Windows, TTY1 elsewhere. */
    public static String platformDefault() {
        return System.getProperty("os.name", "").toLowerCase(Locale.ROOT).startsWith("windows") ? "COM1" : "TTY1";
    }

    /**
     * The handle for a link named on a command line: a device path's last element
     * ({@code /tmp/ttyV0} gives {@code ttyV0}, even when it is a symlink), or
     * {@code tcp-host-port} for {@code tcp://host:port}.
     */
    public static String forLink(String link) {
        if (link.startsWith("tcp://")) {
            URI uri = URI.create(link);
            if (uri.getHost() == null || uri.getPort() < 0) {
                throw new MalformedNameException("'" + link + "' is not tcp://host:port");
            }
            return sanitize("tcp-" + uri.getHost() + "-" + uri.getPort());
        }
        Path name = Path.of(link).getFileName();
        if (name == null) {
            throw new MalformedNameException("'" + link + "' names no device");
        }
        return sanitize(name.toString());
    }

    private static String sanitize(String s) {
        String h = s.replaceAll("[^A-Za-z0-9._\\-]", "-");
        while (h.startsWith(".") || h.startsWith("-") || h.startsWith("_")) {
            h = h.substring(1);
        }
        if (h.isEmpty()) {
            throw new MalformedNameException("'" + s + "' gives no usable mailbox handle");
        }
        return h.length() > 128 ? h.substring(0, 128) : h;
    }

    /** This host's name as services register it: {@code ripv.host} if set, else the canonical name. */
    public static String localHost() {
        String configured = System.getProperty("ripv.host");
        if (configured != null && !configured.isBlank()) {
            return configured.trim();
        }
        try {
            return InetAddress.getLocalHost().getCanonicalHostName();
        } catch (UnknownHostException e) {
            return "localhost";
        }
    }
}
