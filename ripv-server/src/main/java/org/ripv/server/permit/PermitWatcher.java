package org.ripv.server.permit;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The permit file in force on a running server, picked up again when it changes on disk (after
 * {@code ripv passwd}). A file that does not parse, or that has gone, leaves the rules in force.
 */
public final class PermitWatcher {
    private static final Logger log = LoggerFactory.getLogger(PermitWatcher.class);

    private final Path file;
    private volatile PermitFile current;
    private volatile long stamp;
    private final List<Consumer<PermitFile>> listeners = new CopyOnWriteArrayList<>();

    /** Loads the file, writing the template when there is none yet. */
    public PermitWatcher(Path file) throws IOException {
        this.file = file;
        reload();
    }

    public PermitFile current() {
        return current;
    }

    /**
     * Runs {@code listener} with the new rules after each successful reload (rights already granted,
     * such as watches, are checked again by it; docs/permit.md). A listener must not block.
     */
    public void onChange(Consumer<PermitFile> listener) {
        listeners.add(listener);
    }

    /** Reads the file now. */
    public synchronized void reload() throws IOException {
        PermitFile loaded = PermitFile.load(file);
        current = loaded;
        stamp = stamp(file);
        for (Consumer<PermitFile> l : listeners) {
            try {
                l.accept(loaded);
            } catch (RuntimeException e) {
                log.error("re-checking rights after the permit file changed failed", e);
            }
        }
    }

    /** Reads the file again if it changed since the last read; the server calls it now and then. */
    public synchronized void reloadIfChanged() {
        long now = stamp(file);
        if (now == -1) {
            if (stamp != -1) {
                // An editor may be mid-save; never fall back to the template (which has no users).
                log.error("the permit file {} is gone; keeping the rules in force until it is back", file);
                stamp = -1;
            }
            return;
        }
        if (now != stamp) {
            try {
                reload();
                log.info("reloaded the permit file {}", file);
            } catch (IOException | RuntimeException e) {
                stamp = now;
                log.error("the permit file {} is broken; keeping the rules in force: {}", file, e.getMessage());
            }
        }
    }

    private static long stamp(Path p) {
        try {
            return Files.getLastModifiedTime(p).toMillis() ^ Files.size(p);
        } catch (IOException e) {
            return -1;
        }
    }
}
