package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.it.TestSystem;
import org.ripv.server.ServerConfig;
import org.ripv.server.security.SelfSignedTls;
import picocli.CommandLine;

/**
 * Issue 10, item 7 (TLS): before the fix the client port was plain TCP, so passwords crossed in
 * clear and anyone in the middle could pose as the server. Now the server makes its own
 * certificate, clients trust it on first use and refuse, as ssh does, when it changes.
 */
class CertificateChangeAttackTest {
    @TempDir
    Path dir;

    record Run(int code, String out, String err) {}

    static Run cli(int port, Path knownHosts) {
        return cli("localhost:" + port, knownHosts);
    }

    /** {@code ?whoami} as alice through the CLI, to one server or a list ({@code --server A,B}). */
    static Run cli(String servers, Path knownHosts) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int code = new CommandLine(new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(out), new PrintStream(err)))
                .execute("--server", servers, "--known-hosts", knownHosts.toString(), "--user", "alice",
                        "--password", TestSystem.PASSWORD, "--exec", "?whoami");
        return new Run(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    @Test
    void aClientTrustsOnFirstUseAndRefusesAChangedCertificate() throws Exception {
        Path known = dir.resolve("home/.ripv/known_hosts");
        int port;
        String first;
        try (TestSystem a = TestSystem.start(ServerConfig.forTests(dir.resolve("a")))) {
            a.user("alice", "operators");
            port = a.server().port();
            first = a.server().tlsFingerprint();
            assertThat(first).startsWith("SHA256:");
            assertThat(Files.readString(a.dataDir().resolve("tls/server.pass")).trim()).hasSizeGreaterThan(20);
            assertThat(java.nio.file.attribute.PosixFilePermissions.toString(
                    Files.getPosixFilePermissions(a.dataDir().resolve("tls/server.p12")))).isEqualTo("rw-------");

            Run r = cli(port, known);
            assertThat(r.code()).as(r.err()).isZero();
            assertThat(r.out()).contains("alice on client");
            assertThat(r.err()).contains("not seen before").contains(first).contains(known.toString());
            assertThat(Files.readString(known)).isEqualTo("localhost:" + port + " " + first + "\n");

            Run again = cli(port, known);
            assertThat(again.code()).isZero();
            assertThat(again.err()).as("no notice the second time").doesNotContain("not seen before");
        }
        // Someone else answers on that port with another key (a new server, or a man in the middle).
        Path b = dir.resolve("b");
        SelfSignedTls.Identity other = SelfSignedTls.loadOrCreate(b.resolve("tls"));
        assertThat(other.fingerprint()).isNotEqualTo(first);
        try (TestSystem sys = TestSystem.start(ServerConfig.forTests(b).withPorts(port, 0, -1))) {
            sys.user("alice", "operators");
            Run r = cli(port, known);
            assertThat(r.code()).isEqualTo(CliCommand.EXIT_NO_SESSION);
            assertThat(r.err()).contains("THE SERVER'S CERTIFICATE HAS CHANGED").contains(other.fingerprint()).contains(first)
                    .contains(known + " line 1");
            assertThat(r.out()).isEmpty();
        }
    }
}
