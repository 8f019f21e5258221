package org.ripv.client.gui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** The launcher's argument handling, and its answer when there is no display (tests run headless). */
class ClientCommandTest {
    @TempDir
    Path dir;

    int run(ByteArrayOutputStream err, String... args) {
        CommandLine cl = new CommandLine(new ClientCommand(new PrintStream(err, true, StandardCharsets.UTF_8)));
        cl.setErr(new java.io.PrintWriter(err, true, StandardCharsets.UTF_8));
        return cl.execute(args);
    }

    @Test
    void withoutADisplayItPointsAtTheCli() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        assumeTrue(java.awt.GraphicsEnvironment.isHeadless(),
                "this JVM has a display (-Dripv.headless=false): the no-display answer cannot be seen here");
        int code = run(err, "glider-base:4444", "--user", "alice");
        assertThat(code).isEqualTo(ClientCommand.EXIT_USAGE);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("no display")
                .contains("ripv cli --server glider-base:4444 --user alice");
    }

    @Test
    void badArgumentsAreUsageErrors() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        assertThat(run(err, "host:notaport")).isEqualTo(2);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("'notaport'");
        ByteArrayOutputStream err2 = new ByteArrayOutputStream();
        assertThat(run(err2, "--password", "x", "--password-file", "f")).isEqualTo(2);
        assertThat(err2.toString(StandardCharsets.UTF_8)).contains("not both");
        assertThat(run(new ByteArrayOutputStream(), "--no-such-option")).isEqualTo(2);
    }

    @Test
    void passwordFileGivesItsFirstLineOnly() throws Exception {
        Path f = dir.resolve("pw");
        Files.writeString(f, "s3cret pass\r\nsecond line\n");
        assertThat(new String(ClientCommand.readPassword(f))).isEqualTo("s3cret pass");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        assertThat(run(err, "--password-file", dir.resolve("missing").toString())).isEqualTo(1);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("does not exist").contains("install -m 600 /dev/null");
    }
}
