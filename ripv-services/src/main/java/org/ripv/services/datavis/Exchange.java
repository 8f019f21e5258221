package org.ripv.services.datavis;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Pattern;

/**
 * The file exchange of thesis appendix D, shared by the service and the built-in worker
 * (docs/datavis.md says it for workers in any language):
 * <ol>
 * <li>the service writes {@code data.dat} (the canonical data file), then {@code info.dat} (one
 *     line: the output name), each complete before it appears (written under a {@code .tmp} name
 *     and renamed);</li>
 * <li>the worker, seeing both, plots, writes {@code <output>.jpg}, deletes {@code data.dat} and
 *     {@code info.dat}, and then writes {@code ok.dat}: {@code 1} on success, or {@code 0 message};</li>
 * <li>the service, seeing {@code ok.dat}, reads the JPEG and deletes {@code ok.dat} and the JPEG.</li>
 * </ol>
 */
public final class Exchange {
    public static final String DATA = "data.dat";
    public static final String INFO = "info.dat";
    public static final String OK = "ok.dat";
    /** A hand-started worker stops when this file appears (and deletes it). */
    public static final String STOP = "stop.dat";
    public static final String TMP_SUFFIX = ".tmp";
    private static final Pattern OUTPUT = Pattern.compile("[A-Za-z0-9][A-Za-z0-9_\\-]{0,99}");

    private Exchange() {}

    /** Whether {@code name} is a usable output name: letters, digits, '_' and '-', no path, no dot. */
    public static boolean validOutputName(String name) {
        return name != null && OUTPUT.matcher(name).matches();
    }

    /** The JPEG a worker writes for an output name; a name given with ".jpg" is not doubled. */
    public static String jpegName(String output) {
        return output.toLowerCase(Locale.ROOT).endsWith(".jpg") ? output : output + ".jpg";
    }

    /** Writes a file so that it appears complete or not at all. */
    public static void writeAtomically(Path dir, String name, byte[] content) throws IOException {
        Path tmp = dir.resolve(name + TMP_SUFFIX);
        Files.write(tmp, content);
        move(tmp, dir.resolve(name));
    }

    /** Renames {@code tmp} to {@code target} atomically where the file system can. */
    public static void move(Path tmp, Path target) throws IOException {
        try {
            Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /** The first line of a small text file, trimmed; empty when the file is gone or empty. */
    public static Optional<String> firstLine(Path file) throws IOException {
        try {
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            return Optional.of(lines.isEmpty() ? "" : lines.get(0).strip());
        } catch (NoSuchFileException e) {
            return Optional.empty();
        }
    }

    /**
     * Removes every exchange file: data.dat, info.dat, ok.dat, any JPEG and any .tmp. The work
     * directory belongs to the exchange, so anything of these kinds is left over from a plot.
     *
     * @return how many files were removed
     */
    public static int clean(Path dir) throws IOException {
        int removed = 0;
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir)) {
            for (Path f : files) {
                String n = f.getFileName().toString();
                String lower = n.toLowerCase(Locale.ROOT);
                if (n.equals(DATA) || n.equals(INFO) || n.equals(OK) || lower.endsWith(".jpg") || lower.endsWith(".jpeg")
                        || n.endsWith(TMP_SUFFIX)) {
                    try {
                        if (Files.deleteIfExists(f)) {
                            removed++;
                        }
                    } catch (IOException e) {
                        throw new UncheckedIOException("cannot remove " + f, e);
                    }
                }
            }
        }
        return removed;
    }
}
