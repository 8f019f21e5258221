package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.Priority;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.ServerConfig;

/**
 * Issue 23, item 13: transcripts (0644, folders 0755), the audit log (0644) and {@code workflows/}
 * (0755) were readable by every account on the server's host. Every file and folder RIPV keeps is
 * owner-only whatever the umask, and what an older version left is tightened at start.
 */
class FilePermissionsAttackTest {
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    Path dir;

    @Test
    void transcriptsTheAuditTrailAndWorkflowsAreOwnerOnly() throws Exception {
        Path data = dir.resolve("server");
        // What an older version left: a transcript readable by all.
        Path old = data.resolve("transcripts").resolve("old-vehicle")
                .resolve(java.time.LocalDate.now(java.time.ZoneOffset.UTC).minusDays(1) + ".jsonl"); // not yet pruned
        Files.createDirectories(old.getParent());
        Files.writeString(old, "{}\n");
        Files.setPosixFilePermissions(old, PosixFilePermissions.fromString("rw-r--r--"));
        Files.setPosixFilePermissions(old.getParent(), PosixFilePermissions.fromString("rwxr-xr-x"));
        try (TestSystem sys = TestSystem.start(ServerConfig.forTests(data))) {
            sys.user("alice", "operators");
            VehicleConsoleService vehicle = new VehicleConsoleService("localhost", "ru29");
            sys.register(vehicle);
            ClientSocketHandler alice = sys.login("alice"); // an audit line
            vehicle.event(VehicleEvent.SURFACED, "at surface", 41.0, -70.0);
            vehicle.line("a line for the transcript");
            Path wf = dir.resolve("w.wf");
            Files.writeString(wf, "notify \"hello\"\n");
            alice.upload(wf, "w.wf", null);
            assertThat(alice.call("", "?queue add " + vehicle.mailbox() + " w.wf", Priority.NORMAL, T, null).footer().replyText())
                    .contains("queued workflow");
            long end = System.nanoTime() + T.toNanos();
            while (!(has(data.resolve("transcripts"), ".jsonl", 2) && has(data.resolve("audit"), ".log", 1)
                    && Files.isDirectory(data.resolve("workflows")))) {
                assertThat(System.nanoTime()).as("transcript, audit and workflows written").isLessThan(end);
                Thread.sleep(100);
            }
            List<String> open = new ArrayList<>();
            for (String area : List.of("transcripts", "audit", "workflows")) {
                Files.walkFileTree(data.resolve(area), new SimpleFileVisitor<>() {
                    @Override
                    public FileVisitResult preVisitDirectory(Path d, BasicFileAttributes attrs) throws IOException {
                        check(d, "rwx------");
                        return FileVisitResult.CONTINUE;
                    }

                    @Override
                    public FileVisitResult visitFile(Path f, BasicFileAttributes attrs) throws IOException {
                        check(f, "rw-------");
                        return FileVisitResult.CONTINUE;
                    }

                    /** The server writes a file beside its place and renames it: one listed a moment ago may be gone. */
                    @Override
                    public FileVisitResult visitFileFailed(Path f, IOException e) throws IOException {
                        if (e instanceof NoSuchFileException) {
                            return FileVisitResult.CONTINUE;
                        }
                        throw e;
                    }

                    private void check(Path p, String expected) throws IOException {
                        try {
                            String mode = PosixFilePermissions.toString(Files.getPosixFilePermissions(p));
                            if (!mode.equals(expected)) {
                                open.add(data.relativize(p) + " " + mode);
                            }
                        } catch (NoSuchFileException gone) {
                            // renamed into place since it was listed; its new name is checked in its own turn
                        }
                    }
                });
            }
            assertThat(open).as("readable by other accounts (umask here: group and others may read new files)").isEmpty();
        }
    }

    private static boolean has(Path root, String suffix, int n) throws Exception {
        if (!Files.isDirectory(root)) {
            return false;
        }
        try (var all = Files.walk(root)) {
            return all.filter(p -> p.toString().endsWith(suffix)).count() >= n;
        }
    }
}
