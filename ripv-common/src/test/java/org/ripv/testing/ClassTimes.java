package org.ripv.testing;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;

/**
 * Writes each test class's own wall time, from its start to its end (its {@code @BeforeAll} and
 * {@code @AfterAll} included), to {@code target/class-times.txt}: one line per class,
 * {@code SECONDS CLASS START END RESULT}, RESULT {@code TESTS_FAILED} when a test of it failed.
 * Surefire's reports cannot be trusted for this once classes run concurrently (issue 38): they
 * file some test cases under another class that ran at the same time. Registered for every module that has ripv-common's test-jar
 * ({@code META-INF/services}).
 */
public final class ClassTimes implements TestExecutionListener {
    private static final Path FILE = Path.of("target", "class-times.txt");
    private final Map<String, Long> started = new ConcurrentHashMap<>();
    private final Map<String, Instant> startedAt = new ConcurrentHashMap<>();
    private final java.util.Set<String> failed = ConcurrentHashMap.newKeySet();

    @Override
    public void executionStarted(TestIdentifier id) {
        if (id.getSource().orElse(null) instanceof ClassSource) {
            started.put(id.getUniqueId(), System.nanoTime());
            startedAt.put(id.getUniqueId(), Instant.now());
        }
    }

    @Override
    public void executionFinished(TestIdentifier id, TestExecutionResult result) {
        if (result.getStatus() == TestExecutionResult.Status.FAILED
                && id.getSource().orElse(null) instanceof org.junit.platform.engine.support.descriptor.MethodSource m) {
            failed.add(m.getClassName()); // the class itself succeeds when only its tests fail; a skipped test is no failure
        }
        Long t0 = started.remove(id.getUniqueId());
        Instant at = startedAt.remove(id.getUniqueId());
        if (t0 == null || !(id.getSource().orElse(null) instanceof ClassSource c)) {
            return;
        }
        String line = String.format(Locale.ROOT, "%.1f %s %s %s %s%n", (System.nanoTime() - t0) / 1e9, c.getClassName(), at,
                Instant.now(), failed.remove(c.getClassName()) ? "TESTS_FAILED" : result.getStatus());
        synchronized (ClassTimes.class) {
            try {
                Files.createDirectories(FILE.getParent());
                Files.writeString(FILE, line, StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
            } catch (IOException e) {
                // a report, not a test: a read-only folder loses it
            }
        }
    }
}
