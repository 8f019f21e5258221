package org.ripv.server;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.server.permit.PermitFile;

/** The launcher's {@code passwd}, scripted: the password comes from standard input. */
class ServerMainTest {
    @TempDir
    Path dir;

    private static int withStdin(String input, String... args) {
        InputStream old = System.in;
        System.setIn(new ByteArrayInputStream(input.getBytes(StandardCharsets.UTF_8)));
        try {
            return ServerMain.run(args);
        } finally {
            System.setIn(old);
        }
    }

    @Test
    void passwdAddsAUserFromStandardInputAndChangesItLater() throws Exception {
        Path permit = dir.resolve("permit.txt");
        assertThat(withStdin("first secret\n", "passwd", "--permit", permit.toString(), "bob", "--roles", "operators",
                "--iterations", "1000")).isZero();
        assertThat(PermitFile.load(permit).authenticate("bob", "first secret".toCharArray())).isPresent();
        assertThat(withStdin("second secret\n", "passwd", "--permit", permit.toString(), "bob", "--iterations", "1000")).isZero();
        PermitFile p = PermitFile.load(permit);
        assertThat(p.authenticate("bob", "second secret".toCharArray())).isPresent();
        assertThat(p.user("bob").orElseThrow().roles()).containsExactly("operators");
    }

    @Test
    void passwdRefusesAShortPasswordAndAMissingOne() {
        Path permit = dir.resolve("permit.txt");
        assertThat(withStdin("short\n", "passwd", "--permit", permit.toString(), "bob")).isEqualTo(1);
        assertThat(withStdin("", "passwd", "--permit", permit.toString(), "bob")).isEqualTo(1);
        assertThat(ServerMain.run("passwd", "--permit", permit.toString())).isEqualTo(2);
    }

    @Test
    void maxClientsBelowOneIsAUsageErrorQuotingTheValue() {
        java.io.PrintStream old = System.err;
        java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
        System.setErr(new java.io.PrintStream(err, true, StandardCharsets.UTF_8));
        int exit;
        try {
            exit = ServerMain.run("server", "--max-clients", "0", "--port", "0", "--registry-port", "0", "--http-port", "0",
                    "--data", dir.resolve("data").toString());
        } finally {
            System.setErr(old);
        }
        assertThat(exit).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("--max-clients must be at least 1, got 0");
    }

    /** The rules each option mixin keeps ({@code WebOptions}, {@code TlsOptions}, {@code NotifyOptions}), through the command line. */
    @Test
    void theMixinsRulesRefuseWithAUsageErrorNamingTheOptions() {
        String ks = dir.resolve("keystore.p12").toString();
        String[][] cases = {
            {"--web-pages must be at least 2, got 1", "--web-pages", "1"},
            {"--plain and --tls-keystore exclude each other", "--plain", "--tls-keystore", ks},
            {"--tls-keystore needs --tls-password-file", "--tls-keystore", ks},
            {"--smtp-credentials needs --smtp HOST:PORT", "--smtp-credentials", dir.resolve("smtp.properties").toString()},
        };
        for (String[] c : cases) {
            java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of("server", "--port", "0", "--registry-port", "0",
                    "--http-port", "0", "--data", dir.resolve("data").toString()));
            args.addAll(java.util.Arrays.asList(c).subList(1, c.length));
            java.io.PrintStream old = System.err;
            java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
            System.setErr(new java.io.PrintStream(err, true, StandardCharsets.UTF_8));
            int exit;
            try {
                exit = ServerMain.run(args.toArray(String[]::new));
            } finally {
                System.setErr(old);
            }
            assertThat(exit).as(c[0]).isEqualTo(2);
            assertThat(err.toString(StandardCharsets.UTF_8)).as(c[0]).contains(c[0]);
        }
    }
}
