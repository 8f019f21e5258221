package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
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
                try (var all = Files.walk(data.resolve(area))) {
                    for (Path p : (Iterable<Path>) all::iterator) {
                        String mode = PosixFilePermissions.toString(Files.getPosixFilePermissions(p));
                        if (!mode.equals(Files.isDirectory(p) ? "rwx------" : "rw-------")) {
                            open.add(data.relativize(p) + " " + mode);
                        }
                    }
                }
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
