package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.server.ServerConfig;
import org.ripv.server.ServerMain;
import picocli.CommandLine;

/** The client port over TLS, with a key store made by the JDK's keytool. */
class TlsTest {
    @TempDir
    Path dir;

    @Test
    void theCliTalksTlsAndAPlainClientIsRefused() throws Exception {
        Path ks = dir.resolve("server.p12");
        Path pw = dir.resolve("pw");
        Files.writeString(pw, "storepass1\n");
        String keytool = Path.of(System.getProperty("java.home"), "bin", "keytool").toString();
        Process p = new ProcessBuilder(keytool, "-genkeypair", "-alias", "ripv", "-keyalg", "EC", "-dname", "CN=localhost",
                "-ext", "SAN=dns:localhost,ip:127.0.0.1", "-validity", "2", "-storetype", "PKCS12", "-keystore", ks.toString(),
                "-storepass", "storepass1").redirectErrorStream(true).start();
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).isZero();
        Path trust = dir.resolve("trust.p12");
        Path cert = dir.resolve("server.crt");
        run(keytool, "-exportcert", "-alias", "ripv", "-keystore", ks.toString(), "-storepass", "storepass1", "-file", cert.toString());
        run(keytool, "-importcert", "-noprompt", "-alias", "ripv", "-file", cert.toString(), "-storetype", "PKCS12",
                "-keystore", trust.toString(), "-storepass", "trustpass");

        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withTls(ServerMain.tlsContext(ks, pw));
        try (TestSystem sys = TestSystem.start(config)) {
            sys.user("alice", "operators");
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            int code = new CommandLine(new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(out), new PrintStream(err)))
                    .execute("--server", "localhost:" + sys.server().port(), "--user", "alice", "--password", TestSystem.PASSWORD,
                            "--truststore", trust.toString(), "--truststore-password", "trustpass", "--exec", "?ping");
            assertThat(code).as(err.toString(StandardCharsets.UTF_8)).isZero();
            assertThat(out.toString(StandardCharsets.UTF_8)).contains("pong");

            Throwable plain = null;
            try (ClientSocketHandler c = ClientSocketHandler.connectPlain("localhost", sys.server().port())) {
                c.call("", "?ping", org.ripv.messages.Priority.NORMAL, Duration.ofSeconds(5), null);
            } catch (Exception e) {
                plain = e;
            }
            assertThat(plain).as("a plain-TCP client cannot talk to a TLS port").isNotNull();

            // 127.0.0.2 reaches the same server, but the certificate names only localhost and 127.0.0.1.
            err.reset();
            code = new CommandLine(new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(out), new PrintStream(err)))
                    .execute("--server", "127.0.0.2:" + sys.server().port(), "--user", "alice", "--password", TestSystem.PASSWORD,
                            "--truststore", trust.toString(), "--truststore-password", "trustpass", "--exec", "?ping");
            assertThat(code).as("a certificate that does not name the host is refused").isEqualTo(CliCommand.EXIT_NO_SESSION);
        }
    }

    private static void run(String... cmd) throws Exception {
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(output).isZero();
    }
}
