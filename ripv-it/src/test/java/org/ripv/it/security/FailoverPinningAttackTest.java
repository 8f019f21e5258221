package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.it.TestSystem;
import org.ripv.probe.FreePorts;
import org.ripv.server.ServerConfig;
import org.ripv.server.security.SelfSignedTls;

/**
 * Issue 23, item 2: with {@code --server A,B}, a changed certificate on A (the man-in-the-middle
 * signal) was logged as "did not answer", and the CLI trusted B on first use and sent it the
 * password. Now a mismatch stops the whole attempt, and B is trusted only with a certificate
 * already trusted for A or one the operator pinned.
 */
class FailoverPinningAttackTest {
    @TempDir
    Path dir;

    static CertificateChangeAttackTest.Run cli(String servers, Path knownHosts) {
        return CertificateChangeAttackTest.cli(servers, knownHosts);
    }

    /** A server with a certificate of its own (not the tests' shared one). */
    private TestSystem server(String name, int port) throws Exception {
        SelfSignedTls.loadOrCreate(dir.resolve(name).resolve("tls"));
        TestSystem s = TestSystem.start(ServerConfig.forTests(dir.resolve(name)).withPorts(port, 0, -1));
        s.user("alice", "operators");
        return s;
    }

    @Test
    void aChangedCertificateOnTheActiveServerStopsTheAttemptAndAnUnpinnedStandbyIsNotTrusted() throws Exception {
        Path known = dir.resolve("known_hosts");
        int portA = FreePorts.one();
        try (TestSystem a = server("a", portA)) {
            CertificateChangeAttackTest.Run first = cli("localhost:" + portA, known);
            assertThat(first.code()).as(first.err()).isZero();
        }
        try (TestSystem standby = server("b", 0)) {
            String list = "localhost:" + portA + ",localhost:" + standby.server().port();

            // A is down; B answers with a certificate nobody pinned, while A is pinned: refused.
            CertificateChangeAttackTest.Run unpinned = cli(list, known);
            assertThat(unpinned.code()).as(unpinned.out()).isEqualTo(CliCommand.EXIT_NO_SESSION);
            assertThat(unpinned.err()).contains("not seen before").contains("is pinned").contains(standby.server().tlsFingerprint());
            assertThat(unpinned.out()).doesNotContain("alice on client");
            assertThat(Files.readString(known)).doesNotContain(standby.server().tlsFingerprint());

            // A man in the middle on A's port (another key): the attempt stops there; B never sees the password.
            try (TestSystem mitm = server("mitm", portA)) {
                CertificateChangeAttackTest.Run r = cli(list, known);
                assertThat(r.code()).isEqualTo(CliCommand.EXIT_NO_SESSION);
                assertThat(r.err()).contains("THE SERVER'S CERTIFICATE HAS CHANGED").doesNotContain("did not answer");
                assertThat(r.out()).doesNotContain("alice on client");
            }

            // The operator pins B (the fingerprint it printed at its start): now B is used when A is down.
            Files.writeString(known, "localhost:" + standby.server().port() + " " + standby.server().tlsFingerprint() + "\n",
                    StandardCharsets.UTF_8, StandardOpenOption.APPEND);
            CertificateChangeAttackTest.Run pinned = cli(list, known);
            assertThat(pinned.code()).as(pinned.err()).isZero();
            assertThat(pinned.out()).contains("alice on client");
        }
    }

    @Test
    void aStandbyWithTheCertificateOfATrustedServerIsLearned() throws Exception {
        Path known = dir.resolve("known_hosts");
        int portA = FreePorts.one();
        // The tests' shared key store: both servers have the same certificate (the same --tls-keystore).
        try (TestSystem a = TestSystem.start(ServerConfig.forTests(dir.resolve("a")).withPorts(portA, 0, -1))) {
            a.user("alice", "operators");
            assertThat(cli("localhost:" + portA, known).code()).isZero();
        }
        try (TestSystem b = TestSystem.start(ServerConfig.forTests(dir.resolve("b")))) {
            b.user("alice", "operators");
            CertificateChangeAttackTest.Run r = cli("localhost:" + portA + ",localhost:" + b.server().port(), known);
            assertThat(r.code()).as(r.err()).isZero();
            assertThat(Files.readString(known)).contains("localhost:" + b.server().port() + " " + b.server().tlsFingerprint());
        }
    }
}
