package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.DatabaseTarget;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import picocli.CommandLine;

/** The CLI's operator fixes: --json types, get into the current directory, passwords, labelled help, handles. */
class CliOpsTest {
    static final String DB = "<DatabaseServer>::<localhost>TTY1";
    static final String CLOCK = "<ClockService>::<localhost>TTY1";

    @TempDir
    static Path dir;
    static TestSystem sys;
    ByteArrayOutputStream out;
    ByteArrayOutputStream err;

    @BeforeAll
    static void start() throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        sys.register(new ClockService("localhost"));
        DatabaseTarget db = EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1");
        sys.register(new DatabaseServer("localhost", List.of(db), new QueryLimits(1000, 30, QueryLimits.DEFAULT_MAX_RESULT_CHARS)));
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    @BeforeEach
    void streams() {
        out = new ByteArrayOutputStream();
        err = new ByteArrayOutputStream();
    }

    int cli(String... args) {
        List<String> all = new ArrayList<>(List.of("--server", "localhost:" + sys.server().port(), "--user", "alice"));
        all.addAll(List.of(args));
        CliCommand cmd = new CliCommand(new ByteArrayInputStream(new byte[0]),
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
    void jsonTablesCarryNumbersAsNumbersAndNullAsNull() throws Exception {
        Path pw = Files.writeString(dir.resolve("pw"), TestSystem.PASSWORD + "\n");
        int code = cli("--password-file", pw.toString(), "--json", "--exec", "use " + DB, "--exec",
                "SELECT mission_id, CAST(NULL AS INTEGER) AS nothing, CAST(1.5 AS DOUBLE) AS d, CAST(2.25 AS DECIMAL(5,2)) AS m,"
                        + " CAST(9000000000 AS BIGINT) AS big, 'text' AS t, CAST(NULL AS VARCHAR(3)) AS s FROM mission"
                        + " ORDER BY mission_id FETCH FIRST 1 ROWS ONLY");
        assertThat(code).as(err()).isZero();
        String table = out().lines().filter(l -> l.contains("TableResult")).findFirst().orElseThrow();
        assertThat(table).containsPattern("\"rows\":\\[\\[\\d+,null,1\\.5,2\\.25,9000000000,\"text\",null\\]\\]");
        assertThat(err()).as("no ps warning for a password file").doesNotContain("Warning");
    }

    @Test
    void passwordOnTheCommandLineWorksButWarns() {
        int code = cli("--password", TestSystem.PASSWORD, "--exec", "?ping");
        assertThat(code).isZero();
        assertThat(out()).contains("pong");
        assertThat(err()).contains("Warning: --password shows the password to every user of this machine (ps)");
    }

    @Test
    void helpShowsTheClisAndTheServicesHelpEachLabelled() {
        int code = cli("--password", TestSystem.PASSWORD, "--exec", "help", "--exec", "use TTY1", "--exec", "use ");
        assertThat(out()).contains("CLI help").contains("put LOCALFILE [NAME] [--replace|--keep]")
                .contains("Service help: choose a MailBox");
        assertThat(err()).as("TTY1 is the handle of two MailBoxes").contains("names 2 MailBoxes");
        streams();
        code = cli("--password", TestSystem.PASSWORD, "--exec", "use " + CLOCK, "--exec", "help");
        assertThat(out()).contains("CLI help").contains("Service help (" + CLOCK + "): none (ClockService knows time");
        assertThat(code).as("the service's lack of help is no error").isZero();
    }

    /** In a process of its own so that its current directory is a fresh one; the password from $RIPV_PASSWORD. */
    @Test
    void getWithoutADirectorySavesIntoTheCurrentDirectory() throws Exception {
        byte[] data = "glider log\n".repeat(1000).getBytes(StandardCharsets.UTF_8);
        Files.write(sys.downloadDir().resolve("unit17.log"), data);
        Path cwd = Files.createDirectories(dir.resolve("cwd"));
        String java = org.ripv.it.TestJvms.java();
        ProcessBuilder pb = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), "org.ripv.client.ClientMain",
                "cli", "--server", "localhost:" + sys.server().port(), "--user", "alice", "--exec", "get unit17.log")
                .directory(cwd.toFile()).redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        pb.environment().put("RIPV_PASSWORD", TestSystem.PASSWORD);
        pb.environment().put("RIPV_KNOWN_HOSTS", TestSystem.knownHosts().toString()); // test certificates stay out of ~/.ripv
        Process p = pb.start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(output).isZero();
        assertThat(output).contains("saved unit17.log (" + data.length + " bytes) to " + cwd.toRealPath().resolve("unit17.log"))
                .doesNotContain("Exception").doesNotContain("Warning");
        assertThat(Files.readAllBytes(cwd.resolve("unit17.log"))).isEqualTo(data);
        try (var left = Files.list(cwd)) {
            assertThat(left.map(f -> f.getFileName().toString())).containsExactly("unit17.log");
        }
    }

    @Test
    void putNeverReplacesSilentlyAndTakesReplaceOrKeep() throws Exception {
        Path local = Files.writeString(dir.resolve("mission.ma"), "behavior: dive\n");
        assertThat(cli("--password", TestSystem.PASSWORD, "--exec", "put " + local)).as(err()).isZero();
        Files.writeString(local, "behavior: surface\n");
        streams();
        assertThat(cli("--password", TestSystem.PASSWORD, "--exec", "put " + local)).isEqualTo(CliCommand.EXIT_ERROR_REPLY);
        assertThat(err()).contains("FILE_EXISTS").contains("--replace to replace it, or --keep to keep both");
        assertThat(Files.readString(sys.uploadDir().resolve("mission.ma"))).isEqualTo("behavior: dive\n");
        streams();
        assertThat(cli("--password", TestSystem.PASSWORD, "--exec", "put " + local + " --keep", "--exec", "?ulfiles"))
                .as(err()).isZero();
        assertThat(Files.readString(sys.uploadDir().resolve("mission.ma"))).as("the first one kept").isEqualTo("behavior: dive\n");
        try (var files = Files.list(sys.uploadDir())) {
            assertThat(files.map(f -> f.getFileName().toString()).filter(n -> n.startsWith("mission")).count()).isEqualTo(2);
        }
        streams();
        int code = cli("--password", TestSystem.PASSWORD, "--exec", "put " + local + " --replace");
        if (code == 0) {
            assertThat(Files.readString(sys.uploadDir().resolve("mission.ma"))).isEqualTo("behavior: surface\n");
        } else {
            assertThat(err()).as("replacing is a right of its own").contains("may not replace");
        }
    }

    @Test
    void putSaysHowToResolveANameClash() throws Exception {
        Path local = Files.writeString(dir.resolve("plan.ma"), "behavior: surface\n");
        int code = cli("--password", TestSystem.PASSWORD, "--exec", "put " + local + " --replace --keep");
        assertThat(code).isEqualTo(CliCommand.EXIT_ERROR_REPLY);
        assertThat(err()).contains("--replace or --keep, not both");
    }
}
