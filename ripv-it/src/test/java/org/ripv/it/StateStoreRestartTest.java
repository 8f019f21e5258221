package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.Properties;
import java.util.concurrent.ThreadLocalRandom;
import java.util.function.Predicate;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.NotifyList;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.ServerConfig;
import org.ripv.server.SessionOptions;
import org.ripv.server.notify.Smtp;
import org.ripv.server.store.StoreLocation;
import org.ripv.service.ConsoleTap;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 15 point 5: a server keeping its state in PostgreSQL ({@code --state-db}) stops, and a
 * server with a new, empty data directory (another host, as a standby would be) starts on the same
 * database: the transcript, the vehicle's call state, the workflow queue, the receipts and the
 * subscriptions are all there,
 * the queued workflow runs on the next call, and the audit trail holds both servers' log-ins.
 * Needs RIPV_PG_URL (skipped without it, a failure under RIPV_REQUIRE_TOOLS=1).
 */
class StateStoreRestartTest {
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;
    SerialPortServer serial;
    String mb;
    String schema;
    Properties admin;

    @AfterEach
    void stop() throws Exception {
        if (sys != null) {
            sys.close();
        }
        if (glider != null) {
            glider.close();
        }
        if (schema != null) {
            try (Connection c = DriverManager.getConnection(System.getenv("RIPV_PG_URL"), admin); Statement st = c.createStatement()) {
                st.execute("DROP SCHEMA IF EXISTS " + schema + " CASCADE");
            }
        }
    }

    private StoreLocation database() throws Exception {
        String url = System.getenv("RIPV_PG_URL");
        if (url == null || url.isBlank()) {
            if ("1".equals(System.getenv("RIPV_REQUIRE_TOOLS"))) {
                throw new AssertionError("RIPV_REQUIRE_TOOLS=1 but no PostgreSQL: set RIPV_PG_URL (and RIPV_PG_USER)");
            }
            Assumptions.abort("no PostgreSQL: set RIPV_PG_URL (and RIPV_PG_USER, RIPV_PG_PASSWORD) to run this test");
        }
        admin = new Properties();
        admin.setProperty("user", System.getenv().getOrDefault("RIPV_PG_USER", "postgres"));
        admin.setProperty("password", System.getenv().getOrDefault("RIPV_PG_PASSWORD", ""));
        schema = "ripv_it_" + Long.toString(ThreadLocalRandom.current().nextLong(1L << 40), 36).toLowerCase(Locale.ROOT);
        try (Connection c = DriverManager.getConnection(url, admin); Statement st = c.createStatement()) {
            st.execute("CREATE SCHEMA " + schema);
        }
        String pw = admin.getProperty("password");
        return new StoreLocation(url + (url.contains("?") ? "&" : "?") + "currentSchema=" + schema, admin.getProperty("user"),
                pw.isEmpty() ? null : pw);
    }

    /** A server on its own data directory, keeping its state in the database; a glider on its link. */
    private void startServer(Path data, StoreLocation db) throws Exception {
        SessionOptions sessions = SessionOptions.defaults().withSmtp(Smtp.parse("127.0.0.1:9", null));
        sys = TestSystem.start(ServerConfig.forTests(data).withStateStore(db), sessions);
        sys.user("alice", "operators").user("olga", "observers");
        LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + glider.port()).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(SerialEndToEndTest.YMODEM);
        serial = new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("work"));
        sys.register(serial);
        mb = "<SerialPortServer>::<localhost>" + serial.handles().get(0);
    }

    @Test
    void aServerOnANewHostFindsTranscriptsQueuesReceiptsAndSubscriptionsInPostgres() throws Exception {
        StoreLocation db = database();
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), SerialEndToEndTest.YMODEM);
        glider.listen(0);
        startServer(dir.resolve("first"), db);
        ClientSocketHandler alice = sys.login("alice");

        // a call: one workflow runs (a receipt), lines reach the transcript
        upload(alice, "dir.wf", "send dir expect=MISSION1.LOG\n");
        ok(alice, "?queue add " + mb + " dir.wf");
        event(VehicleEvent.SURFACED);
        assertThat(await(alice, "?receipts " + mb, r -> r.contains("result: DONE"))).contains("'dir.wf' of alice");
        for (int i = 0; i < 50; i++) {
            ConsoleTap.publish(serial, ConsoleEntry.line(mb, "before the restart " + i));
        }
        ConsoleTap.publish(serial, ConsoleEntry.line(mb, "quotes \" tab\t ünïcödé"));
        event(VehicleEvent.DIVED);
        // while dived: a second workflow waits, and a subscription is made
        upload(alice, "later.wf", "send dir\n");
        ok(alice, "?queue add " + mb + " later.wf");
        NotifyList sub = (NotifyList) cmd(alice, "?notify add email alice@example.org ALERT *ru*").footer().result();
        String subId = sub.subscriptions().get(0).id();
        assertThat(history(alice, "")).extracting(ConsoleEntry::text).contains("before the restart 49");
        sys.close();
        sys = null;

        // another server, another (empty) data directory, the same database
        Path second = dir.resolve("second");
        startServer(second, db);
        ClientSocketHandler again = sys.login("alice");
        assertThat(ok(again, "?queue " + mb)).contains("later.wf").contains("alice").doesNotContain("dir.wf");
        assertThat(ok(again, "?receipts " + mb)).contains("'dir.wf' of alice").contains("result: DONE");
        List<ConsoleEntry> h = history(again, "");
        assertThat(h).extracting(ConsoleEntry::text).contains("before the restart 0", "before the restart 49",
                "quotes \" tab\t ünïcödé");
        // In the order published: this test's last two entries are the line and the dive. The
        // glider's own link may have printed after them (its banner to the second server's
        // SerialPortServer, later on a loaded machine), so they are found among the test's own.
        List<ConsoleEntry> mine = h.stream().filter(StateStoreRestartTest::publishedHere).toList();
        assertThat(mine.get(mine.size() - 2).text()).isEqualTo("quotes \" tab\t ünïcödé");
        assertThat(mine.get(mine.size() - 1).event()).isEqualTo(VehicleEvent.DIVED);
        assertThat(newest(again, 3)).as("--last 3 is the tail of the whole history").isNotEmpty();
        assertThat(h).anyMatch(e -> e.event() == VehicleEvent.SURFACED);
        // the vehicle's call state came along: dived, not "nothing heard from it yet"; its calls are
        // counted per run of the service, and this SerialPortServer is a new instance that has taken none yet
        org.ripv.messages.SessionState vehicle = ((org.ripv.messages.MailboxStatus) cmd(again, "?status " + mb).footer().result()).session();
        assertThat(vehicle.state()).isEqualTo(org.ripv.messages.SessionState.State.DIVED);
        assertThat(vehicle.calls()).isZero();
        assertThat(vehicle.lastContact()).isPositive();
        NotifyList subs = (NotifyList) cmd(again, "?notify list").footer().result();
        assertThat(subs.subscriptions()).extracting(NotifyList.Subscription::id).containsExactly(subId);
        assertThat(subs.subscriptions().get(0).mailboxes()).isEqualTo("*ru*");

        // the queue is live: the next call runs the waiting workflow
        event(VehicleEvent.SURFACED);
        String both = await(again, "?receipts " + mb, r -> r.split("result: DONE", -1).length - 1 == 2);
        assertThat(both).containsSubsequence("'dir.wf' of alice", "'later.wf' of alice");
        assertThat(ok(again, "?queue " + mb)).contains("empty");

        // nothing of it went to the new data directory's files
        assertThat(second.resolve("workflows").resolve("queues")).doesNotExist();
        assertThat(second.resolve("notify").resolve("subscriptions.jsonl")).doesNotExist();
        try (var files = Files.walk(second.resolve("transcripts"))) {
            assertThat(files.map(Path::toString)).noneMatch(p -> p.endsWith(".jsonl"));
        }
        // the audit trail has both servers' log-ins
        sys.close();
        sys = null;
        try (Connection c = DriverManager.getConnection(db.jdbcUrl(), admin); Statement st = c.createStatement();
             ResultSet rs = st.executeQuery("SELECT count(*) FROM ripv_audit WHERE line LIKE 'login user=alice %'")) {
            rs.next();
            assertThat(rs.getInt(1)).isGreaterThanOrEqualTo(2);
        }
    }

    /** The entries this test published (not the glider's own lines over the live link). */
    private static boolean publishedHere(ConsoleEntry e) {
        return e.kind() == ConsoleEntry.Kind.EVENT ? "test".equals(e.text())
                : e.text().startsWith("before the restart ") || e.text().startsWith("quotes ");
    }

    /**
     * {@code --last n}, checked to be the newest n of the whole history (read before and after it,
     * again if the live link added an entry meanwhile).
     */
    private List<ConsoleEntry> newest(ClientSocketHandler c, int n) throws Exception {
        long end = System.nanoTime() + T.toNanos();
        while (true) {
            List<ConsoleEntry> before = history(c, "");
            List<ConsoleEntry> last = history(c, " --last " + n);
            List<ConsoleEntry> after = history(c, "");
            if (before.equals(after)) {
                assertThat(last).isEqualTo(after.subList(Math.max(0, after.size() - n), after.size()));
                return last;
            }
            assertThat(System.nanoTime()).as("the history kept changing").isLessThan(end);
        }
    }

    private List<ConsoleEntry> history(ClientSocketHandler c, String options) throws Exception {
        OutgoingServerMessage h = cmd(c, "?history " + mb + options);
        assertThat(h.status()).as(h.footer().replyText()).isEqualTo(Status.OK);
        return ((ConsoleBatch) h.footer().result()).entries();
    }

    private void event(VehicleEvent e) throws Exception {
        ConsoleTap.publish(serial, ConsoleEntry.event(mb, e, "test", null, null));
    }

    private void upload(ClientSocketHandler c, String name, String text) throws Exception {
        Path local = dir.resolve("local").resolve(name);
        Files.createDirectories(local.getParent());
        Files.writeString(local, text, StandardCharsets.UTF_8);
        c.upload(local, name, null);
    }

    private static OutgoingServerMessage cmd(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }

    private static String ok(ClientSocketHandler c, String body) throws Exception {
        OutgoingServerMessage r = cmd(c, body);
        assertThat(r.status()).as(body + " -> " + r.footer().replyText()).isEqualTo(Status.OK);
        return r.footer().replyText();
    }

    private static String await(ClientSocketHandler c, String body, Predicate<String> done) throws Exception {
        long end = System.nanoTime() + T.toNanos();
        String last = "";
        while (System.nanoTime() < end) {
            last = cmd(c, body).footer().replyText();
            if (done.test(last)) {
                return last;
            }
            Thread.sleep(100);
        }
        throw new AssertionError("gave up waiting on '" + body + "'; last reply:\n" + last);
    }
}
