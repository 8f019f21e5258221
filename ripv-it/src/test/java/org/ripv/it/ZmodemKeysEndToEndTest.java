package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.testing.Tools;

/**
 * Issue 24 as launched: the SerialPortServer and the CLI run from their jars (the {@code ripv}
 * launcher) against a vehicle whose ZMODEM is lrzsz behind a socat pseudo-terminal. {@code ?key
 * MAILBOX ctrl-c} reaches it and its prompt comes back; a user without the right to
 * {@code ?key ctrl-c}, and a key the link does not list, are refused; {@code zmodem:get} lands
 * byte-identical in the server's download folder and {@code zmodem:put} on the vehicle.
 */
class ZmodemKeysEndToEndTest {
    static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();

    @TempDir
    Path dir;
    TestSystem sys;
    LaunchedJars jars;

    @AfterEach
    void stop() throws InterruptedException {
        if (jars != null) {
            jars.close();
        }
        if (sys != null) {
            sys.close();
        }
    }

    private Process launch(Path log, String... args) throws IOException {
        if (jars == null) {
            jars = new LaunchedJars(dir);
        }
        return jars.launch(log, args);
    }

    /** Runs the CLI from its jar; its exit code and output. */
    private record Cli(int exit, String out) {
    }

    private Cli cli(String user, String... lines) throws Exception {
        List<String> args = new ArrayList<>(List.of("cli", "--server", "localhost:" + sys.server().port(), "--user", user,
                "--password-file", dir.resolve("pw").toString(), "--timeout", "120"));
        for (String l : lines) {
            args.add("--exec");
            args.add(l);
        }
        Path log = Files.createTempFile(dir, "cli", ".log");
        Process p = launch(log, args.toArray(String[]::new));
        assertThat(p.waitFor(180, TimeUnit.SECONDS)).as("the CLI ended").isTrue();
        return new Cli(p.exitValue(), Files.readString(log, StandardCharsets.UTF_8));
    }

    @Test
    void keysAndZmodemThroughTheLaunchedServiceAndCli() throws Exception {
        for (String m : List.of("ripv-server", "ripv-services", "ripv-client")) {
            assumeTrue(Files.isRegularFile(ROOT.resolve(m + "/target/" + m + ".jar")), "needs the jars (mvn verify builds them)");
        }
        Tools.require("socat", "sz", "rz", "bash");
        Files.createDirectories(dir.resolve("home/.ripv"));
        Files.writeString(dir.resolve("pw"), TestSystem.PASSWORD + "\n");
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators").user("bob", "observers");
        sys.rules("allow @operators * * *", "allow @observers * * ?read", "allow bob SerialPortServer * dir",
                "allow bob SerialPortServer * ?key ctrl-r");

        Path vehicle = Files.createDirectories(dir.resolve("vehicle"));
        byte[] log = new byte[150_000];
        new Random(24).nextBytes(log);
        Files.write(vehicle.resolve("01230000.DBD"), log);
        Path pty = dir.resolve("ttyG");
        Path script = ROOT.resolve("ripv-services/src/test/resources/org/ripv/services/serial/zmodem-vehicle.sh");
        Process socat = new ProcessBuilder("socat", "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec bash " + script + " "
                + vehicle + "'").directory(vehicle.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("socat.log").toFile()).start();
        if (jars == null) {
            jars = new LaunchedJars(dir);
        }
        jars.add(socat);
        awaitTrue("socat made " + pty, () -> Files.exists(pty));

        Path secret = dir.resolve("service.secret");
        Files.writeString(secret, sys.secret());
        Path serviceLog = dir.resolve("serial.log");
        launch(serviceLog, "service", "serial", "--server", "localhost:" + sys.server().registryPort(), "--secret-file",
                secret.toString(), "--no-enumerate", "--work", dir.resolve("work").toString(), "--link",
                pty + ",name=ru29,prompt-regex=GliderDOS \\S+ # >,line-ending=cr,idle-timeout=1000,keys=ctrl-c,ctrl-r");
        awaitTrue("the SerialPortServer registered; its log: " + serviceLog, () -> sys.server().serviceCount() > 0);
        String host = java.net.InetAddress.getLocalHost().getHostName();
        Cli boxes = cli("alice", "?mailboxes");
        String mailbox = boxes.out().lines().map(String::strip).filter(l -> l.contains("ru29"))
                .map(l -> l.substring(0, l.indexOf("ru29") + 4)).findFirst().orElseThrow(() -> new AssertionError(
                        "no ru29 in ?mailboxes (" + host + "): " + boxes.out()));
        awaitTrue("ru29 available", () -> cli("alice", "?status " + mailbox).out().contains(": available"));

        Cli ctrlC = cli("alice", "?key " + mailbox + " ctrl-c");
        assertThat(ctrlC.exit()).as(ctrlC.out()).isZero();
        assertThat(ctrlC.out()).contains("sent ctrl-c").contains("Control-C received").contains("GliderDOS A # >");

        Cli bobC = cli("bob", "?key " + mailbox + " ctrl-c");
        assertThat(bobC.exit()).as(bobC.out()).isNotZero();
        assertThat(bobC.out()).contains("may not send '?key ctrl-c'").contains("FORBIDDEN");
        Cli bobR = cli("bob", "use " + mailbox, "key ctrl-r");
        assertThat(bobR.exit()).as(bobR.out()).isZero();
        assertThat(bobR.out()).contains("resuming mission");

        Cli notListed = cli("alice", "?key " + mailbox + " ctrl-e");
        assertThat(notListed.exit()).isNotZero();
        assertThat(notListed.out()).contains("'ctrl-e' is not allowed on ru29; it allows ctrl-c, ctrl-r");

        Cli get = cli("alice", "use " + mailbox, "zmodem:get 01230000.DBD");
        assertThat(get.exit()).as(get.out()).isZero();
        assertThat(get.out()).contains("received 01230000.DBD (150000 bytes)");
        assertThat(Files.readAllBytes(sys.downloaded("01230000.DBD"))).isEqualTo(log);

        byte[] mission = new byte[20_000];
        new Random(25).nextBytes(mission);
        Path local = dir.resolve("goto_l10.ma");
        Files.write(local, mission);
        Cli put = cli("alice", "put " + local, "use " + mailbox, "zmodem:put goto_l10.ma");
        assertThat(put.exit()).as(put.out()).isZero();
        assertThat(Files.readAllBytes(vehicle.resolve("goto_l10.ma"))).isEqualTo(mission);

        Cli history = cli("alice", "?history " + mailbox);
        assertThat(history.out()).contains("alice").contains("?key ctrl-c").contains("bob").contains("?key ctrl-r");
    }

    @FunctionalInterface
    interface Check {
        boolean ok() throws Exception;
    }

    private static void awaitTrue(String what, Check check) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!check.ok()) {
            assertThat(System.nanoTime()).as(what).isLessThan(end);
            TimeUnit.MILLISECONDS.sleep(200);
        }
    }
}
