package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import com.sun.net.httpserver.HttpServer;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.ServerConfig;
import org.ripv.server.SessionOptions;
import org.ripv.server.notify.WebhookTargets;

/**
 * Server-side request forgery through webhooks: a webhook makes the server send HTTP from inside
 * its own network, so a user who may add one could otherwise reach the server's loopback services,
 * the cloud metadata address or the private LAN. Webhooks are a permit right of their own, and go
 * only to public addresses unless the operator allows a range; both are checked again at each
 * delivery, so a subscription made while allowed stops when it no longer is.
 */
class WebhookForgeryAttackTest {
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    Path dir;
    TestSystem sys;
    HttpServer internal;
    final AtomicInteger reached = new AtomicInteger();

    @BeforeEach
    void start() throws Exception {
        // Stands for a service that listens on the server's loopback only (an admin page, a database).
        internal = HttpServer.create(new InetSocketAddress("127.0.0.1", 0), 0);
        internal.createContext("/", x -> {
            reached.incrementAndGet();
            x.sendResponseHeaders(200, -1);
            x.close();
        });
        internal.start();
    }

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
        internal.stop(0);
    }

    private String internalUrl() {
        return "http://127.0.0.1:" + internal.getAddress().getPort() + "/admin";
    }

    private static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }

    @Test
    void webhooksToLoopbackMetadataAndPrivateAddressesAreRefusedByDefault() throws Exception {
        sys = TestSystem.start(dir.resolve("server"));
        sys.user("otto", "operators");
        ClientSocketHandler otto = sys.login("otto");
        int port = internal.getAddress().getPort();
        String[][] refused = {
                {internalUrl(), "loopback"},
                {"http://localhost:" + port + "/", "loopback"},
                {"http://[::1]:" + port + "/", "loopback"},
                {"http://[::ffff:127.0.0.1]:" + port + "/", "loopback"},
                {"http://0.0.0.0:" + port + "/", "unspecified"},
                {"http://169.254.169.254/latest/meta-data/", "link-local"},
                {"http://10.20.30.40/hook", "private"},
                {"http://192.168.1.1/hook", "private"},
                {"http://172.16.0.1/hook", "private"},
                {"http://100.64.0.1/hook", "carrier-grade NAT"},
                {"http://[fd00::1]/hook", "unique-local"},
                {"http://[64:ff9b::7f00:1]/hook", "loopback"},
        };
        for (String[] r : refused) {
            OutgoingServerMessage m = call(otto, "?notify add webhook " + r[0] + " all");
            assertThat(m.status()).as(r[0]).isEqualTo(Status.ERROR);
            assertThat(m.footer().errorCode()).as(r[0]).isEqualTo(ErrorCode.BAD_REQUEST);
            assertThat(m.footer().replyText()).as(r[0]).contains(r[1], "--webhook-allow");
        }
        OutgoingServerMessage creds = call(otto, "?notify add webhook http://user:secret@example.org/hook all");
        assertThat(creds.footer().replyText()).contains("user name or password");
        // A host that does not resolve is refused at once, not stored to fail later.
        assertThat(call(otto, "?notify add webhook http://no-such-host.invalid/hook all").footer().replyText())
                .contains("cannot resolve");
        assertThat(call(otto, "?notify list").footer().replyText()).startsWith("0 subscription(s)");
        assertThat(reached).hasValue(0);
    }

    @Test
    void addingAWebhookIsARightOfItsOwn() throws Exception {
        sys = TestSystem.start(ServerConfig.forTests(dir.resolve("server")),
                SessionOptions.defaults().withWebhooks(WebhookTargets.parse("127.0.0.1/32")));
        sys.user("otto", "operators").user("olga", "observers");
        ClientSocketHandler olga = sys.login("olga");
        OutgoingServerMessage m = call(olga, "?notify add webhook " + internalUrl() + " all");
        assertThat(m.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(m.footer().replyText()).contains("may not add webhooks");
        assertThat(call(sys.login("otto"), "?notify add webhook " + internalUrl() + " all").status()).isEqualTo(Status.OK);
    }

    @Test
    void aSubscriptionMadeWhileAllowedIsRefusedAtDeliveryOnceItIsNot() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server"));
        sys = TestSystem.start(config, SessionOptions.defaults().withWebhooks(WebhookTargets.parse("127.0.0.0/8")));
        sys.user("otto", "operators");
        assertThat(call(sys.login("otto"), "?notify add webhook " + internalUrl() + " SURFACED").status())
                .isEqualTo(Status.OK);
        sys.close();

        // The same data directory, started as deployed: public addresses only.
        sys = TestSystem.start(config);
        sys.user("otto", "operators");
        VehicleConsoleService vehicle = new VehicleConsoleService("localhost", "ru29");
        sys.register(vehicle);
        ClientSocketHandler otto = sys.login("otto");
        vehicle.event(VehicleEvent.SURFACED, "GPS Location: 4137.994 N -7032.188 E", 41.63323, -70.53647);
        long end = System.nanoTime() + T.toNanos();
        String list = "";
        while (System.nanoTime() < end && !list.contains("refused")) {
            Thread.sleep(50);
            list = call(otto, "?notify list").footer().replyText();
        }
        assertThat(list).contains("refused", "loopback");
        assertThat(reached).hasValue(0);
    }
}
