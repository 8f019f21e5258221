package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.probe.FreePorts;
import org.ripv.server.files.FileStore;
import org.ripv.testing.Tools;

/**
 * Issue 24, item 3, as launched: the SerialPortServer runs from its jar with a listen:// link set
 * to {@code to-vehicle=zmodem}, the glider simulator from its jar calls it. Two files uploaded to
 * the vehicle's {@code to-vehicle/} folder through the ordinary upload path go out on its call:
 * one arrives on the glider byte-identical and moves to {@code sent/} with a receipt; the other,
 * which the glider cannot store (a folder of that name is in the way), stays, and goes on the next
 * call once the way is clear. A user without {@code ?to-vehicle}, a name that climbs out of the
 * folder and a folder no MailBox has are refused at upload; another vehicle's file is never sent.
 */
class ToVehicleEndToEndTest {
    static final Path ROOT = LaunchedJars.ROOT;
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path dir;
    TestSystem sys;
    LaunchedJars jars;

    @AfterEach
    void stop() throws Exception {
        if (jars != null) {
            jars.close();
        }
        if (sys != null) {
            sys.close();
        }
    }

    private static String text(ClientSocketHandler c, String body) throws Exception {
        OutgoingServerMessage r = c.call("", body, Priority.NORMAL, T, null);
        return r.footer().replyText();
    }

    private Path local(String name, byte[] data) throws IOException {
        Path p = Files.createDirectories(dir.resolve("local")).resolve(name);
        Files.write(p, data);
        return p;
    }

    @Test
    void filesInToVehicleGoOutOnTheNextCallAndFailuresStay() throws Exception {
        for (String m : List.of("ripv-server", "ripv-services")) {
            assumeTrue(Files.isRegularFile(ROOT.resolve(m + "/target/" + m + ".jar")), "needs the jars (mvn verify builds them)");
        }
        Tools.require("sz", "rz", "bash");
        Files.createDirectories(dir.resolve("home/.ripv"));
        jars = new LaunchedJars(dir);
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators").user("bob", "observers");
        sys.rules("allow @operators * * *", "allow @observers RIPVServer * ?upload*", "allow @observers * * ?read");

        int port = FreePorts.one();
        Path secret = dir.resolve("service.secret");
        Files.writeString(secret, sys.secret());
        Path serviceLog = dir.resolve("serial.log");
        jars.launch(serviceLog, "service", "serial", "--server", "localhost:" + sys.server().registryPort(), "--secret-file",
                secret.toString(), "--no-enumerate", "--work", dir.resolve("work").toString(), "--link",
                "listen://127.0.0.1:" + port + ",name=ru29,idle-timeout=1000,to-vehicle=zmodem");
        awaitTrue("the SerialPortServer registered; its log: " + serviceLog, () -> sys.server().serviceCount() > 0);
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler bob = sys.login("bob");
        String boxes = text(alice, "?mailboxes");
        String mailbox = boxes.lines().map(String::strip).filter(l -> l.contains("ru29"))
                .map(l -> l.substring(0, l.indexOf("ru29") + 4)).findFirst()
                .orElseThrow(() -> new AssertionError("no ru29 in ?mailboxes: " + boxes));
        String folder = FileStore.folderFor(mailbox);
        String to = "to-vehicle/" + folder + "/";

        byte[] mission = new byte[20_000];
        new Random(24).nextBytes(mission);
        byte[] blocked = "behavior_name=surface\n".repeat(50).getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        assertThat(alice.upload(local("goto_l10.ma", mission), to + "goto_l10.ma", null).footer().replyText())
                .contains("stored " + to + "goto_l10.ma (20000 bytes)");
        alice.upload(local("BLOCKED.MI", blocked), to + "BLOCKED.MI", null);
        assertThat(text(alice, "?ulfiles")).contains(to + "goto_l10.ma").contains(to + "BLOCKED.MI");

        // refused at the door: no right, a name that climbs out, a folder no vehicle has
        assertThatThrownBy(() -> bob.upload(local("x.ma", mission), to + "x.ma", null))
                .isInstanceOf(RipvErrorException.class).hasMessageContaining("?to-vehicle " + folder)
                .satisfies(e -> assertThat(((RipvErrorException) e).code()).isEqualTo(ErrorCode.FORBIDDEN));
        assertThatThrownBy(() -> alice.upload(local("evil.ma", mission), "to-vehicle/" + folder + "/../../evil.ma", null))
                .isInstanceOf(RipvErrorException.class).hasMessageContaining("is not a to-vehicle name");
        assertThatThrownBy(() -> alice.upload(local("evil.ma", mission), "to-vehicle/../evil.ma", null))
                .isInstanceOf(RipvErrorException.class).hasMessageContaining("is not a to-vehicle name");
        assertThatThrownBy(() -> alice.upload(local("y.ma", mission), "to-vehicle/nobody@nowhere@None/y.ma", null))
                .isInstanceOf(RipvErrorException.class).hasMessageContaining("no MailBox has the folder 'nobody@nowhere@None'");
        OutgoingServerMessage other = alice.call(mailbox, "tovehicle:put to-vehicle/elsewhere@x@SerialPortServer/goto_l10.ma",
                Priority.NORMAL, T, null);
        assertThat(other.footer().errorCode()).isEqualTo(ErrorCode.BAD_FILE_NAME);
        assertThat(other.footer().replyText()).contains("sends a file of " + mailbox + "'s own folder");
        Path up = sys.uploadDir();
        try (var all = Files.walk(dir)) {
            assertThat(all.filter(p -> p.getFileName().toString().equals("evil.ma") && !p.startsWith(dir.resolve("local"))))
                    .isEmpty();
        }

        // the glider cannot store BLOCKED.MI: a folder of that name is in the way
        Path glider = Files.createDirectories(dir.resolve("glider"));
        Files.createDirectories(glider.resolve("BLOCKED.MI"));
        Process simulator = SimulatorProcess.start(dir.resolve("simulator.log"), List.of("--call", "127.0.0.1:" + port,
                "--name", "ru29", "--surface-seconds", "20", "--dive-seconds", "2", "--dir", glider.toString()));
        jars.add(simulator);

        Path sent = up.resolve("to-vehicle").resolve(folder).resolve("sent");
        awaitTrue("goto_l10.ma moved to sent/; the service's log: " + serviceLog,
                () -> Files.isRegularFile(sent.resolve("goto_l10.ma")), 120);
        assertThat(Files.readAllBytes(glider.resolve("goto_l10.ma"))).isEqualTo(mission);
        assertThat(Files.readAllBytes(sent.resolve("goto_l10.ma"))).isEqualTo(mission);
        assertThat(Files.readString(sent.resolve("goto_l10.ma.receipt"))).contains("file: " + to + "goto_l10.ma")
                .contains("bytes: 20000").contains("uploaded by: alice")
                .contains("the vehicle's dir lists goto_l10.ma with 20000 bytes");
        assertThat(up.resolve("to-vehicle").resolve(folder).resolve("goto_l10.ma")).doesNotExist();
        String history = awaitHistory(alice, mailbox, "BLOCKED.MI stays for the next call");
        assertThat(history).contains("to-vehicle: sent goto_l10.ma (20000 bytes");
        assertThat(up.resolve("to-vehicle").resolve(folder).resolve("BLOCKED.MI")).exists();
        assertThat(sent.resolve("BLOCKED.MI")).doesNotExist();

        // the way is clear: the next call takes it
        Files.delete(glider.resolve("BLOCKED.MI"));
        awaitTrue("BLOCKED.MI moved to sent/ on a later call", () -> Files.isRegularFile(sent.resolve("BLOCKED.MI")), 180);
        assertThat(Files.readAllBytes(glider.resolve("BLOCKED.MI"))).isEqualTo(blocked);
        assertThat(sent.resolve("BLOCKED.MI.receipt")).exists();
        assertThat(text(alice, "?ulfiles")).doesNotContain(to + "BLOCKED.MI").doesNotContain(to + "goto_l10.ma");
    }

    private static String awaitHistory(ClientSocketHandler c, String mailbox, String wanted) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        String last = "";
        while (System.nanoTime() < end) {
            last = text(c, "?history " + mailbox);
            if (last.contains(wanted)) {
                return last;
            }
            TimeUnit.MILLISECONDS.sleep(300);
        }
        throw new AssertionError("no '" + wanted + "' in the history:\n" + last);
    }

    @FunctionalInterface
    interface Check {
        boolean ok() throws Exception;
    }

    private static void awaitTrue(String what, Check check) throws Exception {
        awaitTrue(what, check, 60);
    }

    private static void awaitTrue(String what, Check check, int seconds) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (!check.ok()) {
            assertThat(System.nanoTime()).as(what).isLessThan(end);
            TimeUnit.MILLISECONDS.sleep(200);
        }
    }
}
