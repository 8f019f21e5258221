package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.icegreen.greenmail.util.GreenMail;
import com.icegreen.greenmail.util.GreenMailUtil;
import com.icegreen.greenmail.util.ServerSetup;
import com.sun.net.httpserver.HttpServer;
import jakarta.mail.internet.MimeMessage;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.probe.FreePorts;
import org.ripv.server.ServerConfig;
import org.ripv.server.SessionOptions;
import org.ripv.server.files.FileStore;
import org.ripv.server.notify.Smtp;
import org.ripv.server.notify.WebhookTargets;
import org.ripv.testing.Tools;

/**
 * Issue 36, items 1, 3 and 4, as launched: the SerialPortServer and the glider simulator run
 * from their jars (the simulator calls a {@code listen://} link with {@code to-vehicle=zmodem}).
 * A pilot checks goto files in the upload store ({@code ?plan MAILBOX check}: the table, or
 * {@code FILE:LINE: reason}), sends one as {@code goto_l10.ma} — the file the simulated mission's
 * goto_list reads — and another as {@code goto_l12.ma}, which no behaviour reads, and sets a
 * parameter ({@code ?plan MAILBOX set}). On the next call both files arrive byte for byte and the
 * put is echoed (sent, received); the call after that, the dialog's {@code c_wpt_lat/lon} is a
 * waypoint of goto_l10.ma and {@code sensor:c_dive_target_depth} shows 30 (in effect), while
 * goto_l12.ma shows nowhere: after two surfacings it is not in effect, with an ALERT. A file sent
 * as {@code goto_l15.ma} and taken back ({@code ?delete}) before the call is cancelled and never
 * reaches the glider.
 */
class PlanEndToEndTest {
    static final Path ROOT = LaunchedJars.ROOT;
    static final Duration T = Duration.ofSeconds(60);

    static final String GOTO = "behavior_name=goto_list\n# Written by SFMC on UTC: 2026-11-27T21:02:11\n# goto_l11.ma\n\n"
            + "<start:b_arg>\n\tb_arg: num_legs_to_run(nodim) -1\n\tb_arg: start_when(enum) 0 # BAW_IMMEDIATELY\n"
            + "\tb_arg: list_stop_when(enum) 7 # BAW_WHEN_WPT_DIST\n\tb_arg: initial_wpt(enum) 1 # the second\n"
            + "\tb_arg: num_waypoints(nodim) 3\n<end:b_arg>\n<start:waypoints>\n-7040.12\t4121.50\n-7035.80\t4118.25 # shoal\n"
            + "-7031.44\t4115.00\n<end:waypoints>\n";
    static final String OTHER = GOTO.replace("4121.50", "4021.50").replace("4118.25", "4018.25").replace("4115.00", "4015.00")
            .replace("initial_wpt(enum) 1", "initial_wpt(enum) 0");

    @TempDir
    Path dir;
    TestSystem sys;
    LaunchedJars jars;
    GreenMail mail;
    HttpServer http;
    final List<String> hooked = new CopyOnWriteArrayList<>();

    @AfterEach
    void stop() throws Exception {
        if (http != null) {
            http.stop(0);
        }
        if (mail != null) {
            mail.stop();
        }
        if (jars != null) {
            jars.close();
        }
        if (sys != null) {
            sys.close();
        }
    }

    private static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }

    private Path local(String name, String text) throws IOException {
        Path p = Files.createDirectories(dir.resolve("local")).resolve(name);
        Files.writeString(p, text, StandardCharsets.US_ASCII);
        return p;
    }

    @Test
    void aPlanIsCheckedSentReceivedAndFollowedUntilItIsInEffectOrNot() throws Exception {
        for (String m : List.of("ripv-server", "ripv-services")) {
            assumeTrue(Files.isRegularFile(ROOT.resolve(m + "/target/" + m + ".jar")), "needs the jars (mvn verify builds them)");
        }
        Tools.require("sz", "rz", "bash");
        Files.createDirectories(dir.resolve("home/.ripv"));
        jars = new LaunchedJars(dir);
        // every change of state is an event a webhook and an e-mail subscription get (item 4)
        mail = new GreenMail(new ServerSetup(0, "127.0.0.1", ServerSetup.PROTOCOL_SMTP).dynamicPort());
        mail.setUser("ripv@example.org", "ripv", "mail secret");
        mail.start();
        http = HttpServer.create(new InetSocketAddress("127.0.0.1", 0), 0);
        http.createContext("/plan", x -> {
            hooked.add(new String(x.getRequestBody().readAllBytes(), StandardCharsets.UTF_8));
            x.sendResponseHeaders(200, -1);
            x.close();
        });
        http.start();
        Path credentials = dir.resolve("smtp.properties");
        Files.writeString(credentials, "user=ripv\npassword=mail secret\nfrom=ripv@example.org\n");
        sys = TestSystem.start(ServerConfig.forTests(dir.resolve("sys").resolve("server")), SessionOptions.defaults()
                .withSmtp(Smtp.parse("127.0.0.1:" + mail.getSmtp().getPort(), credentials))
                .withWebhooks(WebhookTargets.parse("127.0.0.1/32")));
        sys.user("alice", "operators").user("bob", "observers");
        sys.rules("allow @operators * * *", "allow @observers RIPVServer * ?upload*", "allow @observers * * ?read");
        int port = FreePorts.one();
        Path secret = dir.resolve("service.secret");
        Files.writeString(secret, sys.secret());
        Path serviceLog = dir.resolve("serial.log");
        jars.launch(serviceLog, "service", "serial", "--server", "localhost:" + sys.server().registryPort(), "--secret-file",
                secret.toString(), "--no-enumerate", "--work", dir.resolve("work").toString(), "--link",
                "listen://127.0.0.1:" + port + ",name=ru29,idle-timeout=1000,to-vehicle=zmodem,alert=leak|LEAK");
        awaitTrue("the SerialPortServer registered; its log: " + serviceLog, () -> sys.server().serviceCount() > 0, 60);
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler bob = sys.login("bob");
        String boxes = call(alice, "?mailboxes").footer().replyText();
        String mailbox = boxes.lines().map(String::strip).filter(l -> l.contains("ru29"))
                .map(l -> l.substring(0, l.indexOf("ru29") + 4)).findFirst()
                .orElseThrow(() -> new AssertionError("no ru29 in ?mailboxes: " + boxes));
        String folder = FileStore.folderFor(mailbox);
        assertThat(call(alice, "?notify add webhook http://127.0.0.1:" + http.getAddress().getPort() + "/plan PLAN_CHANGE").status())
                .isEqualTo(Status.OK);
        assertThat(call(bob, "?notify add email bob@example.org PLAN_CHANGE").status()).isEqualTo(Status.OK);

        alice.upload(local("goto_l11.ma", GOTO), "goto_l11.ma", null);
        alice.upload(local("goto_l13.ma", OTHER), "goto_l13.ma", null);
        alice.upload(local("bad_l14.ma", GOTO.replace("4118.25", "4168.25").replace("<end:waypoints>\n", "")), "bad_l14.ma", null);

        // item 1: the check, by the vehicle's name too
        OutgoingServerMessage check = call(bob, "?plan ru29 check goto_l11.ma");
        assertThat(check.status()).as(check.footer().replyText()).isEqualTo(Status.OK);
        assertThat(check.footer().replyText()).contains("goto_l11.ma: goto_list, 3 waypoint(s), 5 b_arg(s), sha256 ")
                .contains("   1    41.30417    -70.59667  shoal").contains("initial_wpt(enum)");
        TableResult table = (TableResult) check.footer().result();
        assertThat(table.columns()).containsExactly("n", "lat", "lon", "comment");
        assertThat(table.rows()).hasSize(3);
        OutgoingServerMessage bad = call(alice, "?plan " + mailbox + " check bad_l14.ma");
        assertThat(bad.footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
        assertThat(bad.footer().replyText()).contains("bad_l14.ma:14: latitude '4168.25' has 68.25 minutes: minutes must be under 60")
                .contains("bad_l14.ma:12: <start:waypoints> has no <end:waypoints>");

        // item 3: refused files and rights stage nothing; good ones are staged and queued
        OutgoingServerMessage refused = call(alice, "?plan " + mailbox + " send bad_l14.ma as goto_l10.ma");
        assertThat(refused.footer().replyText()).endsWith("nothing was staged");
        OutgoingServerMessage notBob = call(bob, "?plan " + mailbox + " send goto_l11.ma as goto_l10.ma");
        assertThat(notBob.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(call(alice, "?plan " + mailbox + " send goto_l11.ma as ../x.ma").footer().errorCode())
                .isEqualTo(ErrorCode.BAD_REQUEST);
        assertThat(sys.uploadDir().resolve("to-vehicle").resolve(folder)).doesNotExist();
        // item 2: a saved version, with who and when; the diff against the last sent once one was sent
        OutgoingServerMessage saved = call(alice, "?plan ru29 save goto_l11.ma");
        assertThat(saved.footer().replyText()).as(saved.footer().replyText()).startsWith("version 1 of goto_l11.ma for " + mailbox
                + ", saved by alice at ").contains("no earlier version of goto_l11.ma was sent");
        assertThat(call(alice, "?plan ru29 save bad_l14.ma as goto_l11.ma").footer().replyText()).endsWith("no version was kept");
        assertThat(call(bob, "?plan ru29 save goto_l11.ma").footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        OutgoingServerMessage send = call(alice, "?plan " + mailbox + " send goto_l11.ma as goto_l10.ma");
        assertThat(send.status()).as(send.footer().replyText()).isEqualTo(Status.OK);
        assertThat(send.footer().replyText()).contains("change 1: ").contains("staged as to-vehicle/" + folder + "/goto_l10.ma");
        assertThat(call(alice, "?plan " + mailbox + " send goto_l13.ma as goto_l12.ma").status()).isEqualTo(Status.OK);
        OutgoingServerMessage second = call(alice, "?plan ru29 save goto_l13.ma as goto_l11.ma");
        assertThat(second.footer().replyText()).as(second.footer().replyText()).startsWith("version 2 of goto_l11.ma")
                .contains("diff against version 1, the last sent (as goto_l10.ma, change 1, ")
                .contains("\n- -7040.12\t4121.50\n").contains("\n+ -7040.12\t4021.50\n");
        OutgoingServerMessage history = call(bob, "?plan ru29 history goto_l11.ma");
        assertThat(history.footer().replyText()).as(history.footer().replyText()).startsWith("2 version(s) of goto_l11.ma")
                .contains("sent as goto_l12.ma, change 2"); // version 2 is goto_l13.ma's bytes, sent as goto_l12.ma
        List<String[]> versions = ((TableResult) history.footer().result()).rows();
        assertThat(versions).extracting(r -> r[0] + " " + r[2]).containsExactly("1 alice", "2 alice");
        assertThat(versions.get(0)[5]).startsWith("as goto_l10.ma, change 1, ");
        assertThat(versions.get(1)[5]).startsWith("as goto_l12.ma, change 2, ");
        OutgoingServerMessage set = call(alice, "?plan " + mailbox + " set c_dive_target_depth 30");
        assertThat(set.footer().replyText()).as(set.footer().replyText()).contains("change 3: 'put c_dive_target_depth 30' queued");
        assertThat(call(alice, "?plan " + mailbox + " send goto_l11.ma as goto_l10.ma").footer().errorCode())
                .isEqualTo(ErrorCode.FILE_EXISTS);
        assertThat(call(alice, "?changes " + mailbox).footer().replyText()).contains("3 change(s) for " + mailbox)
                .contains("   1  queued         goto_l10.ma (from goto_l11.ma)").contains("   3  queued         put c_dive_target_depth 30");
        // a staged file taken back before the call: its change is cancelled at once, and nothing of it reaches the glider
        assertThat(call(alice, "?plan " + mailbox + " send goto_l13.ma as goto_l15.ma").footer().replyText()).contains("change 4: ");
        OutgoingServerMessage delete = call(alice, "?delete to-vehicle/" + folder + "/goto_l15.ma");
        assertThat(delete.status()).as(delete.footer().replyText()).isEqualTo(Status.OK);
        assertThat(call(alice, "?changes " + mailbox).footer().replyText()).contains("   4  cancelled      goto_l15.ma (from goto_l13.ma)")
                .contains("the staged file to-vehicle/" + folder + "/goto_l15.ma was deleted before a call took it");

        // the glider calls: 12 s at the surface, 2 s dives
        Path glider = Files.createDirectories(dir.resolve("glider"));
        Process simulator = SimulatorProcess.start(dir.resolve("simulator.log"), List.of("--call", "127.0.0.1:" + port,
                "--name", "ru29", "--surface-seconds", "12", "--dive-seconds", "2", "--dir", glider.toString()));
        jars.add(simulator);

        String changes = awaitChanges(alice, mailbox, "   1  in effect", 150);
        assertThat(Files.readString(glider.resolve("goto_l10.ma"), StandardCharsets.US_ASCII)).isEqualTo(GOTO);
        assertThat(Files.readString(glider.resolve("goto_l12.ma"), StandardCharsets.US_ASCII)).isEqualTo(OTHER);
        assertThat(glider.resolve("goto_l15.ma")).doesNotExist();
        changes = awaitChanges(alice, mailbox, "   3  in effect", 60);
        assertThat(changes).contains("c_wpt_lat/lon 41.30417, -70.59667 is waypoint 1")
                .contains("sensor:c_dive_target_depth=30");
        changes = awaitChanges(alice, mailbox, "   2  not in effect", 90);
        assertThat(changes).contains("2 surfacings without it").contains("is none of the file's 3 waypoints");

        String events = call(alice, "?history " + mailbox + " --last 1000").footer().replyText();
        assertThat(events).contains("change 1 goto_l10.ma (from goto_l11.ma): queued")
                .contains("change 1 goto_l10.ma (from goto_l11.ma): sent")
                .contains("change 1 goto_l10.ma (from goto_l11.ma): received: the vehicle's dir lists goto_l10.ma with its size; sha256 "
                        + sha256(GOTO))
                .contains("change 3 put c_dive_target_depth 30: received: the vehicle echoed sensor:c_dive_target_depth=30")
                .contains("change 2 goto_l12.ma (from goto_l13.ma) is not in effect")
                .contains("change 4 goto_l15.ma (from goto_l13.ma): cancelled: the staged file");
        assertThat(events.lines().filter(l -> l.contains("ALERT") && l.contains("change 2 goto_l12.ma"))).hasSize(1);
        // item 5: the forecast from the simulated glider's last fix (calls under a minute apart: the assumed speed)
        OutgoingServerMessage forecast = call(alice, "?plan ru29 forecast goto_l11.ma");
        assertThat(forecast.status()).as(forecast.footer().replyText()).isEqualTo(Status.OK);
        assertThat(forecast.footer().replyText()).contains("forecast of goto_l11.ma for " + mailbox + " from its fix at ")
                .contains("speed 0.3 m/s (assumed").contains("no current known");
        assertThat(((TableResult) forecast.footer().result()).rows()).extracting(r -> r[0]).containsExactly("1", "2", "0");
        assertThat(call(alice, "?plan ru29 forecast goto_l11.ma 0.6").footer().replyText()).contains("speed 0.6 m/s (given)");
        assertThat(call(alice, "?plan ru29 forecast goto_l11.ma 99").footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
        // the webhook and the e-mail got the changes of state, the cancel among them
        assertThat(hooked).anySatisfy(b -> assertThat(b).contains("\"event\":\"PLAN_CHANGE\"").contains("goto_l15.ma (from goto_l13.ma): cancelled"))
                .anySatisfy(b -> assertThat(b).contains("change 1 goto_l10.ma (from goto_l11.ma): in effect"));
        assertThat(mail.waitForIncomingEmail(T.toMillis(), 5)).isTrue();
        MimeMessage[] got = mail.getReceivedMessages();
        assertThat(got).anySatisfy(m -> assertThat(m.getSubject()).isEqualTo("[RIPV] ru29 PLAN_CHANGE"));
        assertThat(java.util.Arrays.stream(got).map(GreenMailUtil::getBody)).anySatisfy(b -> assertThat(b).contains("in effect"));
        // the fleet view lists what is not settled: nothing now
        assertThat(call(bob, "?changes").footer().replyText()).startsWith("0 pending change(s)");
    }

    private static String sha256(String text) throws Exception {
        return java.util.HexFormat.of().formatHex(java.security.MessageDigest.getInstance("SHA-256")
                .digest(text.getBytes(StandardCharsets.US_ASCII)));
    }

    private static String awaitChanges(ClientSocketHandler c, String mailbox, String wanted, int seconds) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        String last = "";
        while (System.nanoTime() < end) {
            last = call(c, "?changes " + mailbox).footer().replyText();
            if (last.contains(wanted)) {
                return last;
            }
            TimeUnit.MILLISECONDS.sleep(500);
        }
        throw new AssertionError("no '" + wanted + "' in ?changes:\n" + last + "\n\nhistory:\n"
                + call(c, "?history " + mailbox + " --last 300").footer().replyText());
    }

    @FunctionalInterface
    interface Check {
        boolean ok() throws Exception;
    }

    private static void awaitTrue(String what, Check check, int seconds) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (!check.ok()) {
            assertThat(System.nanoTime()).as(what).isLessThan(end);
            TimeUnit.MILLISECONDS.sleep(200);
        }
    }
}
