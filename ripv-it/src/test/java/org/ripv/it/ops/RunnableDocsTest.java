package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.server.ServerConfig;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.DatabaseTarget;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.datavis.DataVisServer;

/**
 * Every command in the docs' blocks marked runnable ({@code ```sh runnable}, see docs/README.md)
 * works: run through the real {@code ./ripv} with bash, offline, against a server this test starts
 * (user alice, HOME a temporary directory holding {@code ~/.ripv/pw} and {@code ~/ripv-data}, the
 * DatabaseServer, DataVisServer and ClockService on host {@code localhost}). Every {@code ripv cli}
 * is pointed at that server; programs that run until stopped ({@code ripv server}, {@code service},
 * {@code simulator}, {@code client}, {@code demo}) and {@code ripv passwd} without piped input run
 * with {@code RIPV_PARSE_ONLY=1}: their command line is checked (an unknown option fails) and
 * nothing starts.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class RunnableDocsTest {
    static final Path ROOT = RipvScriptHelpTest.ROOT;
    static final Pattern RIPV = Pattern.compile("(^|[|;&]\\s*)(\\./)?ripv(?=\\s|$)");
    static final Pattern LONG_RUNNING = Pattern.compile("(\\./)?ripv\\s+(server|service|simulator|client|demo)\\b|--follow\\b");

    @TempDir
    static Path tmp;
    TestSystem sys;
    Path home;
    Path work;

    static Stream<RunnableDocs.Command> commands() throws Exception {
        List<RunnableDocs.Command> all = new ArrayList<>();
        for (Path doc : RunnableDocs.documents(ROOT)) {
            all.addAll(RunnableDocs.commands(doc));
        }
        return all.stream();
    }

    @BeforeAll
    void start() throws Exception {
        for (String m : List.of("ripv-common", "ripv-server", "ripv-services", "ripv-client")) {
            assumeTrue(Files.isRegularFile(ROOT.resolve(m + "/target/" + m + ".jar")),
                    "needs the jars (mvn package; mvn verify builds them before this module's tests)");
        }
        home = Files.createDirectories(tmp.resolve("home"));
        work = Files.createDirectories(tmp.resolve("work"));
        Files.createSymbolicLink(work.resolve("docs"), ROOT.resolve("docs")); // docs/samples/... as in the source tree
        Files.createDirectories(home.resolve(".ripv"));
        Files.writeString(home.resolve(".ripv/pw"), TestSystem.PASSWORD + "\n");
        sys = TestSystem.start(ServerConfig.forTests(home.resolve("ripv-data")));
        sys.user("alice", "operators");
        sys.register(new ClockService("localhost"));
        DatabaseTarget db = EmbeddedDatabase.prepare(tmp.resolve("database"), "TTY1");
        sys.register(new DatabaseServer("localhost", List.of(db), new QueryLimits(1000, 30, QueryLimits.DEFAULT_MAX_RESULT_CHARS)));
        sys.register(new DataVisServer("localhost", DataVisServer.Config.of(tmp.resolve("vis"))));
    }

    @AfterAll
    void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    @Test
    void aTrailingCommentIsNoPartOfTheCommand() {
        assertThat(RunnableDocs.withoutComment("./ripv server --data ~/d   # clients on 4444")).isEqualTo("./ripv server --data ~/d   ");
        assertThat(RunnableDocs.withoutComment("./ripv cli --exec 'SELECT 1 # not a comment'")).endsWith("comment'");
        assertThat(RunnableDocs.withoutComment("echo a#b")).isEqualTo("echo a#b");
    }

    @Test
    void theDocsMarkARepresentativeSetOfCommandsRunnable() throws Exception {
        List<String> texts = commands().map(RunnableDocs.Command::text).toList();
        assertThat(texts).hasSizeGreaterThanOrEqualTo(15);
        for (String c : List.of(" cli ", " server", " passwd", " service ", " bench", "--json", "put ", "get ", "vis:", "SELECT")) {
            assertThat(texts).as("a runnable command with '" + c + "'").anyMatch(t -> t.contains(c));
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("commands")
    void everyRunnableCommandInTheDocsWorks(RunnableDocs.Command command) throws Exception {
        String line = rewrite(command.text());
        boolean dryRun = LONG_RUNNING.matcher(command.text()).find() || (command.text().matches(".*\\bripv\\s+passwd\\b.*")
                && !(command.text().contains("|") && command.text().indexOf('|') < command.text().indexOf("passwd")));
        Path log = Files.createTempFile(tmp, "command", ".log");
        ProcessBuilder pb = new ProcessBuilder("bash", "-o", "pipefail", "-c", line).directory(work.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        ProcessWatch watch = new ProcessWatch();
        pb.environment().put(ProcessWatch.VARIABLE, watch.mark);
        pb.environment().put("HOME", home.toString());
        pb.environment().remove("RIPV_PASSWORD");
        pb.environment().remove("DISPLAY");
        if (dryRun) {
            pb.environment().put("RIPV_PARSE_ONLY", "1");
        }
        Process p = pb.start();
        boolean ended = p.waitFor(120, TimeUnit.SECONDS);
        var left = watch.processes();
        for (String s : left) { // nothing a documented command started may outlive it
            ProcessHandle.of(Long.parseLong(s.substring(0, s.indexOf(' ')))).ifPresent(ProcessHandle::destroyForcibly);
        }
        p.destroyForcibly();
        String out = Files.readString(log, StandardCharsets.UTF_8);
        assertThat(ended).as(command + " still running after 120 s:\n" + out).isTrue();
        assertThat(left).as(command + " left processes").isEmpty();
        assertThat(p.exitValue()).as(command + "\nran as: " + line + "\n" + out).isZero();
        assertThat(out).as(command.toString()).doesNotContain("Exception").doesNotContain("Error:");
    }

    /** Points the command at this test's script and server. */
    String rewrite(String text) {
        String line = RIPV.matcher(text).replaceAll(m -> Matcher.quoteReplacement(m.group(1) + ROOT.resolve("ripv")));
        if (text.matches(".*\\bripv\\s+cli\\b.*")) {
            line = line.replaceAll("--server\\s+\\S+", "--server localhost:" + sys.server().port());
        }
        return line;
    }

    @Test
    void aDryRunStillRefusesAnOptionThatDoesNotExist() throws Exception {
        for (String c : List.of("./ripv server --data ~/d --no-such-option", "./ripv service serial --server localhost --no-such-option",
                "./ripv demo --no-such-option")) {
            ProcessBuilder pb = new ProcessBuilder("bash", "-c", rewrite(c)).directory(work.toFile()).redirectErrorStream(true);
            pb.environment().put("RIPV_PARSE_ONLY", "1");
            Process p = pb.start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
            assertThat(p.exitValue()).as(c + ": " + out).isEqualTo(2);
        }
    }
}
