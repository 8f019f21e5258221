package org.ripv.it.console;

import static org.assertj.core.api.Assertions.assertThat;

import com.icegreen.greenmail.util.GreenMail;
import com.icegreen.greenmail.util.ServerSetup;
import jakarta.mail.internet.MimeMessage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.cli.CliCommand;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.ServerConfig;
import org.ripv.server.SessionOptions;
import org.ripv.server.notify.Smtp;
import org.ripv.server.permit.PermitFile;
import picocli.CommandLine;

/**
 * Rights taken away while in use: when the permit file on disk changes so that a user may no
 * longer read a MailBox, the running server (by its own periodic look at the file) ends that
 * user's watch with one message saying why — the CLI's {@code --follow} prints it and exits 1 —
 * and stops that user's notifications about it, while everyone else carries on.
 */
class RightsChangeTest {
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    Path dir;
    TestSystem sys;
    GreenMail mail;
    VehicleConsoleService vehicle;
    String box;

    @BeforeEach
    void start() throws Exception {
        mail = new GreenMail(new ServerSetup(0, "127.0.0.1", ServerSetup.PROTOCOL_SMTP).dynamicPort());
        mail.setUser("ripv@example.org", "ripv", "mail secret");
        mail.start();
        Path credentials = dir.resolve("smtp.properties");
        Files.writeString(credentials, "user=ripv\npassword=mail secret\nfrom=ripv@example.org\n");
        Smtp smtp = Smtp.parse("127.0.0.1:" + mail.getSmtp().getPort(), credentials);
        sys = TestSystem.start(ServerConfig.forTests(dir.resolve("server")),
                SessionOptions.defaults().withSmtp(smtp).withNotifyTiming(Duration.ofMillis(200), Duration.ofSeconds(2)));
        sys.user("alice", "operators").user("olga", "observers");
        vehicle = new VehicleConsoleService("localhost", "ru29");
        sys.register(vehicle);
        box = vehicle.mailbox();
    }

    @AfterEach
    void stop() {
        sys.close();
        mail.stop();
    }

    static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }

    /** Every unasked console message a client gets, errors included. */
    static final class Unasked implements ClientSocketHandler.Listener {
        final List<OutgoingServerMessage> got = new CopyOnWriteArrayList<>();

        @Override
        public void onReply(OutgoingServerMessage r) {
            if (r.footer().serviceId().equals(Ids.FID_CONSOLE)) {
                got.add(r);
            }
        }

        List<OutgoingServerMessage> errors() {
            return got.stream().filter(r -> r.status() == Status.ERROR).toList();
        }
    }

    private static void waitFor(java.util.function.BooleanSupplier ok) throws InterruptedException {
        long end = System.nanoTime() + T.toNanos();
        while (!ok.getAsBoolean() && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        assertThat(ok.getAsBoolean()).isTrue();
    }

    /** As {@code ripv passwd --roles} would: olga keeps her password but is no longer an observer. */
    private void olgaLosesHerRole() throws Exception {
        PermitFile.setUser(sys.dataDir().resolve("permit.txt"), "olga", TestSystem.PASSWORD.toCharArray(), List.of(), 1000);
    }

    @Test
    void aWatcherWhoLosesTheReadRightIsToldOnceAndHearsNothingMore() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler olga = sys.login("olga");
        Pushes a = Pushes.on(alice);
        Pushes o = Pushes.on(olga);
        Unasked toOlga = new Unasked();
        olga.addListener(toOlga);
        assertThat(call(alice, "?watch " + box).status()).isEqualTo(Status.OK);
        assertThat(call(olga, "?watch " + box).status()).isEqualTo(Status.OK);
        assertThat(call(olga, "?notify add email olga@example.org SURFACED,DIVED " + box).status()).isEqualTo(Status.OK);
        assertThat(call(alice, "?notify add email alice@example.org SURFACED,DIVED " + box).status()).isEqualTo(Status.OK);

        vehicle.line("before the change");
        vehicle.event(VehicleEvent.SURFACED, "Glider ru29 at surface", 41.5, -70.5);
        assertThat(o.await(e -> e.event() == VehicleEvent.SURFACED, T)).isTrue();
        assertThat(mail.waitForIncomingEmail(T.toMillis(), 2)).isTrue(); // both were notified

        olgaLosesHerRole(); // on disk only: the server notices by itself
        waitFor(() -> !toOlga.errors().isEmpty());
        OutgoingServerMessage end = toOlga.errors().get(0);
        assertThat(end.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(end.footer().replyText()).contains("watch of " + box + " ended", "user 'olga' may not read " + box,
                "the permit file changed");
        assertThat(((ConsoleBatch) end.footer().result()).entries()).singleElement()
                .satisfies(e -> assertThat(e.text()).isEqualTo("[" + end.footer().replyText() + "]"));
        assertThat(sys.server().console().watcherCount()).isEqualTo(1);

        int olgaHad = o.entries.size();
        vehicle.line("after the change");
        vehicle.event(VehicleEvent.DIVED, "", null, null);
        assertThat(a.await(e -> e.event() == VehicleEvent.DIVED, T)).isTrue();
        assertThat(a.texts()).contains("before the change", "after the change");
        // Alice's e-mail about the dive arrives; olga's does not (nor later: checked with the list below).
        assertThat(mail.waitForIncomingEmail(T.toMillis(), 3)).isTrue();
        Thread.sleep(1_000); // anything still on its way to olga would arrive now (alice's went the same way)
        assertThat(o.entries).hasSize(olgaHad); // nothing after the line that ended her watch
        assertThat(o.texts().get(olgaHad - 1)).startsWith("[watch of " + box + " ended");
        assertThat(o.texts()).doesNotContain("after the change");
        assertThat(toOlga.errors()).hasSize(1); // told once
        List<String> to = new ArrayList<>();
        for (MimeMessage m : mail.getReceivedMessages()) {
            to.add(m.getAllRecipients()[0] + " " + m.getSubject());
        }
        assertThat(to).containsExactlyInAnyOrder("olga@example.org [RIPV] ru29 SURFACED",
                "alice@example.org [RIPV] ru29 SURFACED", "alice@example.org [RIPV] ru29 DIVED");
        assertThat(mail.getReceivedMessages()).hasSize(3);

        // She cannot watch again, nor read the history; her connection itself is fine.
        assertThat(call(olga, "?watch " + box).footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(call(olga, "?history " + box).footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(call(olga, "?whoami").status()).isEqualTo(Status.OK);
    }

    @Test
    void followEndsWithTheReasonAndExitCodeOne() throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        List<String> args = List.of("--server", "localhost:" + sys.server().port(), "--user", "olga",
                "--password", TestSystem.PASSWORD, "--follow", box);
        CliCommand cmd = new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        CompletableFuture<Integer> exit = CompletableFuture.supplyAsync(() -> new CommandLine(cmd).execute(args.toArray(String[]::new)));
        vehicle.line("first line");
        waitFor(() -> out.toString(StandardCharsets.UTF_8).contains("first line"));

        olgaLosesHerRole();
        assertThat(exit.get(20, TimeUnit.SECONDS)).isEqualTo(CliCommand.EXIT_ERROR_REPLY);
        String printed = out.toString(StandardCharsets.UTF_8);
        assertThat(printed).containsOnlyOnce("ended: user 'olga' may not read " + box);
        assertThat(printed.lines().toList().get(printed.lines().toList().size() - 1))
                .contains("[watch of " + box + " ended:", "the permit file changed]");
    }

    private static String listText(ClientSocketHandler c) {
        try {
            return call(c, "?notify list").footer().replyText();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }
}
