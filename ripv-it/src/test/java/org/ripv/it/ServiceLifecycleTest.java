package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.server.permit.PermitFile;

/** A service process's life as an operator sees it, and the permit file changing under a running server. */
class ServiceLifecycleTest {
    @TempDir
    Path dir;

    private static Process clock(TestSystem sys, Path log, String secretFile) throws Exception {
        String java = TestJvms.java();
        return new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), "-Dripv.host=lifecycle",
                "org.ripv.examples.ClockService", "--server", "localhost:" + sys.server().registryPort(),
                "--secret-file", secretFile).redirectErrorStream(true).redirectOutput(log.toFile()).start();
    }

    @Test
    void aServiceStoppedBySigtermLeavesCleanlyAndAWrongSecretEndsItWithAnError() throws Exception {
        try (TestSystem sys = TestSystem.start(dir.resolve("server"))) {
            Path log = dir.resolve("clock.log");
            Process p = clock(sys, log, sys.server().secretFile().toString());
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (sys.server().serviceCount() == 0) {
                assertThat(System.nanoTime()).as("registered").isLessThan(end);
                Thread.sleep(100);
            }
            p.destroy(); // SIGTERM
            assertThat(p.waitFor(20, TimeUnit.SECONDS)).isTrue();
            assertThat(p.exitValue()).isEqualTo(143);
            assertThat(Files.readString(log)).doesNotContain("Error:");
            // The server notices at its liveness checks (two failed, 0.5 s apart) that it is gone;
            // only then does "no service registered" below say anything about the next one.
            long gone = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
            while (sys.server().serviceCount() != 0) {
                assertThat(System.nanoTime()).as("the stopped service removed").isLessThan(gone);
                Thread.sleep(100);
            }

            Path wrong = dir.resolve("wrong.secret");
            Files.writeString(wrong, "not-the-secret-at-all");
            Path log2 = dir.resolve("clock2.log");
            Process q = clock(sys, log2, wrong.toString());
            // With the wrong secret the server's proof cannot be checked: the service cannot tell an
            // impostor from a wrong secret file, says both, sends nothing derived from its secret,
            // and gives up after 5 tries with an error (docs/security.md; --retry-forever keeps trying).
            assertThat(q.waitFor(90, TimeUnit.SECONDS)).as(Files.readString(log2, StandardCharsets.UTF_8)).isTrue();
            assertThat(q.exitValue()).isEqualTo(1);
            assertThat(Files.readString(log2, StandardCharsets.UTF_8)).contains("cannot prove it holds the service secret",
                    "--secret-file", "gave up after 5 tries");
            assertThat(sys.server().serviceCount()).isZero();
            q.destroy();
            assertThat(q.waitFor(20, TimeUnit.SECONDS)).isTrue();
        }
    }

    @Test
    void thePermitFileIsReloadedWhenItChangesAndKeptWhenItVanishes() throws Exception {
        try (TestSystem sys = TestSystem.start(dir.resolve("server"))) {
            Path permit = sys.dataDir().resolve("permit.txt");
            // ripv passwd on a running server: no reload call, the server notices the change.
            PermitFile.setUser(permit, "late", TestSystem.PASSWORD.toCharArray(), List.of("operators"), 1000);
            ClientSocketHandler c = null;
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
            while (c == null) {
                try {
                    c = sys.login("late");
                } catch (RipvErrorException e) {
                    assertThat(System.nanoTime()).as("the new user can log in").isLessThan(end);
                    Thread.sleep(200);
                }
            }
            Files.delete(permit);
            Thread.sleep(2000); // a few checks pass while it is gone
            assertThat(permit).as("never rewritten from the template").doesNotExist();
            assertThat(sys.login("late").session().user()).isEqualTo("late");
            assertThat(c.call("", "?ping", org.ripv.messages.Priority.NORMAL, Duration.ofSeconds(10), null).footer().replyText())
                    .isEqualTo("pong");
        }
    }
}
