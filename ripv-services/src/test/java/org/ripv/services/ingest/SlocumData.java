package org.ripv.services.ingest;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/**
 * The shared real glider files ({@code ../shared/data/slocum-binary} beside the repository: data
 * files, their caches, and what Teledyne's {@code dbd2asc} prints for each).
 */
public final class SlocumData {
    private SlocumData() {}

    /** The folder, found from the repository root (the module's parent); the test is skipped when it is absent. */
    public static Path dir() {
        Path root = Path.of("").toAbsolutePath();
        while (root != null && !Files.isRegularFile(root.resolve("ripv"))) {
            root = root.getParent();
        }
        Path d = root == null ? null : root.resolve("../shared/data/slocum-binary").normalize();
        assumeTrue(d != null && Files.isDirectory(d.resolve("realtime_raw")),
                "needs the shared Slocum binary data in ../shared/data/slocum-binary beside the repository (CI has it)");
        return d;
    }

    public static List<Path> files() throws IOException {
        try (Stream<Path> s = Files.list(dir().resolve("realtime_raw"))) {
            return s.sorted().toList();
        }
    }

    public static String expected(Path file) throws IOException {
        return Files.readString(dir().resolve("expected").resolve(file.getFileName() + ".dbd2asc.txt"));
    }

    /**
     * A cache holding the shared cache files, in a copy of this JVM's own: a cache keeps the lists of
     * the files it decodes, and tests decode made-up files, whose lists must not land in the shared
     * data (they did: 0600 files among the 0444 originals).
     */
    public static synchronized SensorListCache cache() throws IOException {
        if (copy == null) {
            Path to = Files.createTempDirectory("ripv-cac-");
            try (Stream<Path> s = Files.list(dir().resolve("cac"))) {
                for (Path f : s.toList()) {
                    Files.copy(f, to.resolve(f.getFileName()));
                }
            }
            copy = to;
        }
        return new SensorListCache(copy);
    }

    private static Path copy;
}
