package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.examples.ClockService;
import picocli.CommandLine;

/** {@code ripv cli} against a real server, as a script would use it. */
class CliTest {
    @TempDir
    Path dir;
    TestSystem sys;
    final ByteArrayOutputStream out = new ByteArrayOutputStream();
    final ByteArrayOutputStream err = new ByteArrayOutputStream();

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        sys.register(new ClockService("localhost"));
    }

    @AfterEach
    void stop() {
        sys.close();
    }

    int cli(String stdin, String... args) {
        List<String> all = new ArrayList<>(List.of("--server", "localhost:" + sys.server().port(), "--user", "alice"));
        all.addAll(List.of(args));
        CliCommand cmd = new CliCommand(new ByteArrayInputStream(stdin.getBytes(StandardCharsets.UTF_8)),
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        return new CommandLine(cmd).execute(all.toArray(String[]::new));
    }

    String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    @Test
    void listsServicesAndTalksToAMailbox() {
        int code = cli("", "--password", TestSystem.PASSWORD, "--exec", "?services",
                "--exec", "use <ClockService>::<localhost>TTY1", "--exec", "echo hello glider");
        assertThat(code).as(err()).isZero();
        assertThat(out()).contains("<ClockService>::<localhost>  SID 100100").contains("hello glider");
    }

    @Test
    void readsLinesFromStandardInputAndExitsNonZeroOnAnyError() {
        int code = cli("?ping\nuse <ClockService>::<localhost>TTY1\nnonsense\necho still works\n", "--password", TestSystem.PASSWORD);
        assertThat(code).isEqualTo(CliCommand.EXIT_ERROR_REPLY);
        assertThat(out()).contains("pong").contains("still works");
        assertThat(err()).contains("Error: ClockService knows time");
    }

    @Test
    void jsonPrintsOneObjectPerReply() {
        int code = cli("", "--password", TestSystem.PASSWORD, "--json", "--exec", "?ulfiles", "--exec", "?whoami");
        assertThat(code).isZero();
        String[] lines = out().strip().split("\n");
        assertThat(lines).hasSize(2);
        assertThat(lines[0]).startsWith("{\"id\":").contains("\"status\":\"OK\"").contains("\"serviceId\":\"444455\"")
                .contains("\"type\":\"FileListing\"");
        assertThat(lines[1]).contains("\"user\":\"alice\"");
    }

    @Test
    void putAndGetMoveFilesBothWays() throws Exception {
        Path local = dir.resolve("binary.bin");
        byte[] data = new byte[700_000];
        new java.util.Random(3).nextBytes(data);
        Files.write(local, data);
        int code = cli("", "--password", TestSystem.PASSWORD, "--exec", "put " + local, "--exec", "?ulfiles");
        assertThat(code).as(err()).isZero();
        assertThat(out()).contains("stored binary.bin (700000 bytes)");
        assertThat(err()).contains("put binary.bin");
        assertThat(Files.readAllBytes(sys.uploadDir().resolve("binary.bin"))).isEqualTo(data);

        Files.write(sys.downloadDir().resolve("mission.log"), data);
        Path back = dir.resolve("back");
        code = cli("", "--password", TestSystem.PASSWORD, "--exec", "get mission.log " + back);
        assertThat(code).as(err()).isZero();
        assertThat(Files.readAllBytes(back.resolve("mission.log"))).isEqualTo(data);
    }

    @Test
    void aWrongPasswordExitsWithItsOwnCode() {
        assertThat(cli("", "--password", "nope", "--exec", "?services")).isEqualTo(CliCommand.EXIT_NO_SESSION);
        assertThat(err()).contains("log-in refused: wrong user name or password");
    }

    @Test
    void anUnreachableServerSaysSo() {
        CliCommand cmd = new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(out), new PrintStream(err));
        int code = new CommandLine(cmd).execute("--server", "localhost:1", "--user", "a", "--password", "b", "--exec", "?ping");
        assertThat(code).isEqualTo(CliCommand.EXIT_NO_SESSION);
        assertThat(err()).contains("cannot connect to localhost:1");
    }
}
