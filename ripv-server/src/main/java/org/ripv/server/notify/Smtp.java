package org.ripv.server.notify;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;

/**
 * The SMTP server e-mail notifications go through ({@code --smtp HOST:PORT}), with credentials
 * from a file ({@code --smtp-credentials FILE}: {@code user=}, {@code password=}, optionally
 * {@code from=} and {@code starttls=true}), so no password is on the command line.
 *
 * @param from the sender address (default {@code ripv@HOST})
 */
public record Smtp(String host, int port, String user, String password, String from, boolean startTls) {

    @Override
    public String toString() {
        return "Smtp[" + host + ":" + port + (user == null ? "" : ", user " + user) + ", from " + from + "]";
    }

    /** Parses {@code HOST:PORT} and reads the optional credentials file. */
    public static Smtp parse(String hostPort, Path credentials) throws IOException {
        int colon = hostPort.lastIndexOf(':');
        if (colon <= 0 || colon == hostPort.length() - 1) {
            throw new IllegalArgumentException("--smtp takes HOST:PORT, not '" + hostPort + "'");
        }
        String host = hostPort.substring(0, colon);
        int port;
        try {
            port = Integer.parseInt(hostPort.substring(colon + 1));
        } catch (NumberFormatException e) {
            port = -1;
        }
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("--smtp: the port in '" + hostPort + "' must be 1-65535");
        }
        String user = null;
        String password = null;
        String from = "ripv@" + (host.contains(".") ? host : "localhost");
        boolean startTls = false;
        if (credentials != null) {
            Properties p = new Properties();
            try (Reader r = Files.newBufferedReader(credentials, StandardCharsets.UTF_8)) {
                p.load(r);
            }
            user = blankToNull(p.getProperty("user"));
            password = blankToNull(p.getProperty("password"));
            from = p.getProperty("from", from).trim();
            startTls = Boolean.parseBoolean(p.getProperty("starttls", "false").trim());
            if (user != null && password == null) {
                throw new IllegalArgumentException(credentials + ": a user= needs a password=");
            }
        }
        return new Smtp(host, port, user, password, from, startTls);
    }

    private static String blankToNull(String s) {
        return s == null || s.isBlank() ? null : s.trim();
    }
}
