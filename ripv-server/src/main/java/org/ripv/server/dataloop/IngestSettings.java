package org.ripv.server.dataloop;

import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Properties;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Which downloads are ingested, from {@code DATA/ingest.properties} (read again when it changes):
 * <pre>
 * # on by default; off turns automatic ingest off for every vehicle not named below
 * auto = on
 * # per vehicle: the glider's name in the file (filename: cp_388-...), or the serial MailBox's handle
 * vehicle.cp_388 = off
 * link.TTY2 = off
 * # the DatabaseServer MailBox to ingest into (default: the first DatabaseServer's first MailBox)
 * database = &lt;DatabaseServer&gt;::&lt;host&gt;TTY1
 * </pre>
 */
final class IngestSettings {
    private static final Logger log = LoggerFactory.getLogger(IngestSettings.class);

    private final Path file;
    private long loadedStamp = Long.MIN_VALUE;
    private Properties props = new Properties();

    IngestSettings(Path file) {
        this.file = file;
    }

    /** Whether a DBA file of glider {@code vehicle} fetched through MailBox {@code handle} is ingested. */
    synchronized boolean enabled(String vehicle, String handle) {
        Properties p = current();
        String v = vehicle == null ? null : p.getProperty("vehicle." + vehicle);
        if (v == null && handle != null) {
            v = p.getProperty("link." + handle);
        }
        if (v == null) {
            v = p.getProperty("auto", "on");
        }
        return switch (v.strip().toLowerCase(Locale.ROOT)) {
            case "off", "false", "no", "0" -> false;
            default -> true;
        };
    }

    /** The configured DatabaseServer MailBox, or null for the default. */
    synchronized String database() {
        String d = current().getProperty("database");
        return d == null || d.isBlank() ? null : d.strip();
    }

    private Properties current() {
        try {
            long stamp = Files.getLastModifiedTime(file).toMillis() ^ Files.size(file);
            if (stamp != loadedStamp) {
                Properties p = new Properties();
                try (Reader r = Files.newBufferedReader(file)) {
                    p.load(r);
                }
                props = p;
                loadedStamp = stamp;
                log.info("read automatic-ingest settings from {}", file);
            }
        } catch (NoSuchFileException e) {
            props = new Properties();
            loadedStamp = Long.MIN_VALUE;
        } catch (IOException | IllegalArgumentException e) {
            log.warn("cannot read {}: {}; keeping the settings read before", file, e.toString());
        }
        return props;
    }
}
