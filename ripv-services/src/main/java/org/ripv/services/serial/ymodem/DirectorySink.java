package org.ripv.services.serial.ymodem;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileTime;
import java.util.Comparator;
import java.util.HashMap;
import java.util.Map;
import org.ripv.files.PrivateFiles;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Receives files into a directory: each is written as a hidden {@code .NAME.part} and renamed
 * to NAME only when its last block has arrived; a failed one is deleted.
 */
public final class DirectorySink implements FileSink {
    private static final Logger log = LoggerFactory.getLogger(DirectorySink.class);
    private final Path dir;
    private final Map<String, Path> parts = new HashMap<>();

    public DirectorySink(Path dir) throws IOException {
        this.dir = PrivateFiles.createDirectories(dir);
    }

    /**
     * Readies a work directory at start: creates it owner-only (0700, also when it existed) and
     * deletes what an earlier run left there: {@code .NAME.part} files and {@code get-N}
     * transfer directories (a crash or kill mid-transfer).
     */
    public static void prepareWorkDir(Path workDir) {
        try {
            PrivateFiles.createDirectories(workDir);
            PrivateFiles.restrict(workDir);
        } catch (IOException e) {
            log.warn("cannot prepare the work directory {}: {}", workDir, e.toString());
            return;
        }
        try (var walk = Files.walk(workDir)) {
            walk.sorted(Comparator.reverseOrder()).filter(p -> !p.equals(workDir)).forEach(p -> {
                String n = p.getFileName().toString();
                boolean inTransfer = workDir.relativize(p).getName(0).toString().startsWith("get-");
                if (inTransfer || n.startsWith(".") && n.endsWith(".part")) {
                    try {
                        Files.deleteIfExists(p);
                    } catch (IOException e) {
                        log.warn("could not delete stale {}: {}", p, e.toString());
                    }
                }
            });
        } catch (IOException e) {
            log.warn("could not clean {}: {}", workDir, e.toString());
        }
    }

    /** Deletes a transfer's directory and all in it (what is left of a transfer); a failure is logged, not thrown. */
    public static void deleteTree(Path dir) {
        if (!Files.exists(dir)) {
            return;
        }
        try (var walk = Files.walk(dir)) {
            walk.sorted(Comparator.reverseOrder()).forEach(p -> {
                try {
                    Files.deleteIfExists(p);
                } catch (IOException e) {
                    log.warn("could not delete {}: {}", p, e.toString());
                }
            });
        } catch (IOException e) {
            log.warn("could not clean {}: {}", dir, e.toString());
        }
    }

    @Override
    public OutputStream begin(FileHeader file) throws IOException {
        String name = FileNames.requirePlain(file.name());
        Path part = dir.resolve("." + name + ".part");
        parts.put(name, part);
        return PrivateFiles.newOutputStream(part, StandardOpenOption.WRITE,
                StandardOpenOption.TRUNCATE_EXISTING); // owner-only: a vehicle's files are not for every local user
    }

    @Override
    public void complete(FileHeader file) throws IOException {
        Path part = parts.remove(file.name());
        Path target = dir.resolve(file.name());
        try {
            Files.move(part, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(part, target, StandardCopyOption.REPLACE_EXISTING);
        }
        if (file.mtimeSeconds() > 0) {
            Files.setLastModifiedTime(target, FileTime.fromMillis(file.mtimeSeconds() * 1000));
        }
    }

    @Override
    public void discard(FileHeader file) {
        Path part = parts.remove(file.name());
        if (part != null) {
            try {
                Files.deleteIfExists(part);
            } catch (IOException e) {
                log.warn("could not delete partial file {}: {}", part, e.toString());
            }
        }
    }

    public Path directory() {
        return dir;
    }
}
