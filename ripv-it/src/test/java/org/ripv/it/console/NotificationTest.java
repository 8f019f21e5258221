package org.ripv.it.console;

import static org.assertj.core.api.Assertions.assertThat;

import com.icegreen.greenmail.util.GreenMail;
import com.icegreen.greenmail.util.GreenMailUtil;
import com.icegreen.greenmail.util.ServerSetup;
import com.sun.net.httpserver.HttpExchange;
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
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.NotifyList;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.ServerConfig;
import org.ripv.server.SessionOptions;
import org.ripv.server.notify.WebhookTargets;
import org.ripv.server.notify.Smtp;

/**
 * Notifications end to end: SURFACED and DIVED reach a real local HTTP receiver and a real SMTP
 * server (GreenMail); a webhook that hangs and one that answers 500 hold up nothing else; a
 * subscriber without the read right hears nothing.
 */
class NotificationTest {
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    Path dir;
    TestSystem sys;
    GreenMail mail;
    HttpServer http;
    VehicleConsoleService vehicle;
    final List<String> good = new CopyOnWriteArrayList<>();
    final List<String> eve = new CopyOnWriteArrayList<>();
    final AtomicInteger failing = new AtomicInteger();
    final AtomicInteger hanging = new AtomicInteger();
    final CountDownLatch hangUntil = new CountDownLatch(1);

    @BeforeEach
    void start() throws Exception {
        mail = new GreenMail(new ServerSetup(0, "127.0.0.1", ServerSetup.PROTOCOL_SMTP).dynamicPort());
        mail.setUser("ripv@example.org", "ripv", "mail secret");
        mail.start();
        http = HttpServer.create(new InetSocketAddress("127.0.0.1", 0), 0);
        http.setExecutor(Executors.newCachedThreadPool());
        http.createContext("/good", x -> answer(x, 200, good));
        http.createContext("/eve", x -> answer(x, 200, eve));
        http.createContext("/fail", x -> {
            failing.incrementAndGet();
            answer(x, 500, null);
        });
        http.createContext("/hang", x -> {
            hanging.incrementAndGet();
            try {
                hangUntil.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            answer(x, 200, null);
        });
        http.start();
        Path credentials = dir.resolve("smtp.properties");
        Files.writeString(credentials, "user=ripv\npassword=mail secret\nfrom=ripv@example.org\n");
        Smtp smtp = Smtp.parse("127.0.0.1:" + mail.getSmtp().getPort(), credentials);
        sys = TestSystem.start(ServerConfig.forTests(dir.resolve("server")),
                SessionOptions.defaults().withSmtp(smtp).withNotifyTiming(Duration.ofMillis(200), Duration.ofSeconds(2))
                        .withWebhooks(WebhookTargets.parse("127.0.0.1/32"))); // the receivers here are on loopback
        sys.user("alice", "operators").user("olga", "observers").user("eve");
        // eve may add webhooks (a right of its own) but may read no MailBox.
        sys.rules("allow @operators * * *", "allow @observers * * ?read", "allow eve RIPVServer * ?webhook *");
        vehicle = new VehicleConsoleService("localhost", "ru29");
        sys.register(vehicle);
    }

    private static void answer(HttpExchange x, int code, List<String> into) throws IOException {
        byte[] body = x.getRequestBody().readAllBytes();
        if (into != null) {
            into.add(x.getRequestHeaders().getFirst("Content-Type") + " " + new String(body, StandardCharsets.UTF_8));
        }
        x.sendResponseHeaders(code, -1);
        x.close();
    }

    @AfterEach
    void stop() {
        hangUntil.countDown();
        sys.close();
        http.stop(0);
        mail.stop();
    }

    private String url(String path) {
        return "http://127.0.0.1:" + http.getAddress().getPort() + path;
    }

    static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }

    static void waitFor(java.util.function.BooleanSupplier ok, Duration d) throws InterruptedException {
        long end = System.nanoTime() + d.toNanos();
        while (!ok.getAsBoolean() && System.nanoTime() < end) {
            Thread.sleep(20);
        }
    }

    @Test
    void surfacedAndDivedReachWebhookAndMailWhileBadReceiversHoldUpNothing() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler olga = sys.login("olga");
        ClientSocketHandler evil = sys.login("eve");
        String box = vehicle.mailbox();
        assertThat(call(alice, "?notify add webhook " + url("/hang") + " all").status()).isEqualTo(Status.OK);
        assertThat(call(alice, "?notify add webhook " + url("/fail") + " SURFACED").status()).isEqualTo(Status.OK);
        OutgoingServerMessage added = call(alice, "?notify add webhook " + url("/good") + " surfaced,DIVED *ru29");
        assertThat(added.status()).isEqualTo(Status.OK);
        assertThat(added.footer().serviceId()).isEqualTo(Ids.FID_NOTIFY);
        assertThat(call(olga, "?notify add email olga@example.org SURFACED,DIVED").status()).isEqualTo(Status.OK);
        assertThat(call(evil, "?notify add webhook " + url("/eve") + " all").status()).isEqualTo(Status.OK);
        Pushes watched = Pushes.on(olga);
        call(olga, "?watch " + box);

        vehicle.line("Glider ru29 at surface.");
        vehicle.event(VehicleEvent.SURFACED, "GPS Location: 4137.994 N -7032.188 E", 41.63323, -70.53647);
        vehicle.line("battery 14.2 V");
        vehicle.event(VehicleEvent.DIVED, "", null, null);

        // The console and the good receivers get everything while /hang still holds its request.
        assertThat(watched.await(e -> e.event() == VehicleEvent.DIVED, T)).isTrue();
        waitFor(() -> good.size() >= 2, T);
        assertThat(good).hasSize(2);
        assertThat(hanging.get()).isGreaterThanOrEqualTo(1);
        assertThat(good.get(0)).startsWith("application/json").contains("\"event\":\"SURFACED\"", "\"vehicle\":\"ru29\"",
                "\"lat\":41.63323", "\"lon\":-70.53647", "\"mailbox\":\"" + box + "\"");
        assertThat(good.get(1)).contains("\"event\":\"DIVED\"", "\"state\":\"dived\"", "\"lat\":41.63323");

        assertThat(mail.waitForIncomingEmail(T.toMillis(), 2)).isTrue();
        MimeMessage[] got = mail.getReceivedMessages();
        assertThat(got[0].getSubject()).isEqualTo("[RIPV] ru29 SURFACED");
        assertThat(got[0].getAllRecipients()[0].toString()).isEqualTo("olga@example.org");
        String body = GreenMailUtil.getBody(got[0]);
        assertThat(body).contains("Vehicle:  ru29", "Event:    SURFACED", "Position: 41.63323, -70.53647",
                "Glider ru29 at surface.");
        assertThat(got[1].getSubject()).isEqualTo("[RIPV] ru29 DIVED");
        assertThat(GreenMailUtil.getBody(got[1])).contains("battery 14.2 V");

        // The 500 is tried ATTEMPTS times with back-off, then given up; ?notify list says so.
        waitFor(() -> failing.get() >= 4, T);
        assertThat(failing.get()).isEqualTo(4);
        waitFor(() -> listText(alice).contains("gave up"), T);
        String list = listText(alice);
        assertThat(list).contains("HTTP 500", "gave up after 4 tries", "ok 200");
        NotifyList mine = (NotifyList) call(alice, "?notify list").footer().result();
        assertThat(mine.subscriptions()).hasSize(3).allMatch(s -> s.user().equals("alice"));
        // The one without the read right heard nothing.
        assertThat(eve).isEmpty();
        assertThat(listText(evil)).contains("never used");
    }

    private static String listText(ClientSocketHandler c) {
        try {
            return call(c, "?notify list").footer().replyText();
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    @Test
    void subscriptionsAreCheckedRemovableAndSurviveARestart() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        assertThat(call(alice, "?notify add webhook ftp://example.org/x all").footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
        assertThat(call(alice, "?notify add webhook " + url("/good") + " BOGUS").footer().replyText()).contains("unknown event 'BOGUS'");
        assertThat(call(alice, "?notify add email not-an-address all").status()).isEqualTo(Status.ERROR);
        assertThat(call(alice, "?notify add pigeon x all").status()).isEqualTo(Status.ERROR);
        assertThat(call(alice, "?notify").status()).isEqualTo(Status.ERROR);
        NotifyList one = (NotifyList) call(alice, "?notify add webhook " + url("/good") + " ALERT").footer().result();
        NotifyList two = (NotifyList) call(alice, "?notify add email alice@example.org all *glider*").footer().result();
        String keep = two.subscriptions().get(0).id();
        assertThat(call(sys.login("olga"), "?notify remove " + keep).status()).isEqualTo(Status.ERROR);
        assertThat(call(alice, "?notify remove " + one.subscriptions().get(0).id()).status()).isEqualTo(Status.OK);

        ServerConfig config = ServerConfig.forTests(sys.dataDir());
        sys.close();
        sys = TestSystem.start(config);
        sys.user("alice", "operators");
        NotifyList after = (NotifyList) call(sys.login("alice"), "?notify list").footer().result();
        assertThat(after.subscriptions()).hasSize(1);
        assertThat(after.subscriptions().get(0).id()).isEqualTo(keep);
        assertThat(after.subscriptions().get(0).channel()).isEqualTo("email");
        assertThat(after.subscriptions().get(0).mailboxes()).isEqualTo("*glider*");
    }

    @Test
    void anSmtpServerThatIsDownHoldsUpNothing() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        call(alice, "?notify add email alice@example.org SURFACED");
        call(alice, "?notify add webhook " + url("/good") + " SURFACED");
        mail.stop();
        vehicle.event(VehicleEvent.SURFACED, "", 41.0, -70.0);
        waitFor(() -> good.size() >= 1, T);
        assertThat(good).hasSize(1);
        waitFor(() -> listText(alice).contains("MailConnectException") || listText(alice).contains("Exception"), T);
        assertThat(listText(alice)).contains("failed (");
    }
}
