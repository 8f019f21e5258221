package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.TablePages;
import org.ripv.messages.TableResult;
import org.ripv.wire.FrameCodec;

/**
 * Issue 38, query results stream, as launched: {@code ripv-server.jar} and the DatabaseServer from
 * {@code ripv-services.jar}, each with a heap smaller than the result (40 MiB of text in 100,000
 * rows; the server {@code -Xmx48m}, the service {@code -Xmx40m}, both exiting on an
 * OutOfMemoryError), so the query can only come through if no process holds it whole. A client
 * gets every row in order; a client that stops reading after the first page and sends
 * {@code ?cancel} gets CANCELLED, and the cancel stopped the statement: the MailBox, which runs
 * one command at a time, answers the next at once.
 */
class QueryStreamEndToEndTest {
    static final int ROWS = 100_000;
    /** 400 characters a row: the result's text is 40 MB, more than the heap of either process. */
    static final String PAD = "x".repeat(400);
    static final Duration T = Duration.ofSeconds(240);

    @TempDir
    Path tmp;

    @RegisterExtension
    final LaunchedSystem sys = new LaunchedSystem().startup(T);

    @Test
    void aResultLargerThanEveryHeapStreamsInOrderAndACancelMidResultStopsTheStatement() throws Exception {
        LaunchedSystem.assumeJars();
        // a heap smaller than the result; the last -Xmx on the command line is the one the JVM takes
        Process server = sys.startServer(List.of("-Xmx48m", "-XX:+ExitOnOutOfMemoryError"), "--plain");
        Process service = sys.startService("database", List.of("-Xmx40m", "-XX:+ExitOnOutOfMemoryError"), "database",
                "--data", tmp.resolve("db").toString(),
                "--max-rows", "1000000", "--max-result-chars", "1000000000", "--query-timeout", "600");

        try (ClientSocketHandler c = loginWhenThePermitFileIsRead(sys.clientPort)) {
            String db = awaitDatabase(c, service);
            setUp(c, db);

            // 1. Every row, in order, through both heaps.
            long t0 = System.nanoTime();
            OutgoingServerMessage r = c.call(db, "SELECT n, label FROM wide ORDER BY n", Priority.NORMAL, T, null);
            assertThat(r.status()).as(r.footer().replyText() + "\n" + sys.log("database")).isEqualTo(Status.OK);
            TableResult t = (TableResult) r.footer().result();
            assertThat(t.rows()).hasSize(ROWS);
            long chars = 0;
            for (int i = 0; i < ROWS; i++) {
                String[] row = t.rows().get(i);
                assertThat(row[0]).isEqualTo(Integer.toString(i + 1));
                assertThat(row[1]).isEqualTo((i + 1) + PAD);
                chars += row[0].length() + row[1].length();
            }
            assertThat(t.truncated()).isFalse();
            assertThat(chars).as("the result's text is larger than either heap").isGreaterThan(40_000_000L);
            assertThat(r.footer().replyText()).startsWith(ROWS + " rows in ");
            System.out.printf("100,000 rows, %d MB of text, in %d ms%n", chars / 1_000_000, (System.nanoTime() - t0) / 1_000_000);
            t = null;
            r = null;
            assertThat(server.isAlive()).as("the server (-Xmx48m) lives: " + sys.log("server")).isTrue();
            assertThat(service.isAlive()).as("the service (-Xmx40m) lives: " + sys.log("database")).isTrue();

            // 2. A client that stops reading after the first page, then cancels.
            cancelMidResult(sys.clientPort, db);
            long t1 = System.nanoTime();
            OutgoingServerMessage next = c.call(db, "SELECT COUNT(*) AS n FROM wide", Priority.NORMAL, T, null);
            assertThat(next.status()).as(next.footer().replyText()).isEqualTo(Status.OK);
            assertThat(((TableResult) next.footer().result()).rows().get(0)[0]).isEqualTo(Integer.toString(ROWS));
            assertThat(Duration.ofNanos(System.nanoTime() - t1)).as("the MailBox was free: the statement had stopped")
                    .isLessThan(Duration.ofSeconds(30));
            // The cancel's interrupt reaches the query either while it waits for its reader ('cancelled while sending
            // its rows') or inside Derby, which closes the connection ("cancelled: Connection closed by unknown
            // interrupt"; the next command reconnects): both stopped the statement, as the free MailBox above shows.
            assertThat(sys.log("database"))
                    .containsPattern("'SELECT a\\.n, b\\.label FROM wide a, wide b' cancelled( while sending its rows|: )");
            assertThat(server.isAlive() && service.isAlive()).isTrue();
        }
    }

    /** Reads the first page, stops reading (the way fills up and the query waits), sends ?cancel, then reads to the end. */
    private void cancelMidResult(int port, String db) throws Exception {
        try (Socket s = new Socket()) {
            s.setReceiveBufferSize(16 * 1024);
            s.connect(new InetSocketAddress("localhost", port), 10_000);
            s.setSoTimeout((int) T.toMillis());
            DataOutputStream out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
            DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream()));
            FrameCodec codec = new FrameCodec(FrameCodec.DEFAULT_MAX_FRAME);
            FrameCodec.writeGreeting(out);
            FrameCodec.readGreeting(in);
            codec.write(out, new IncomingServerMessage(new Header(1, new IdBadge("000000", "alice"), List.of(), "", "",
                    "?login alice", Priority.URGENT, new Attachment("password", TestSystem.PASSWORD.getBytes(StandardCharsets.UTF_8)))));
            assertThat(until(codec, in, 1).status()).isEqualTo(Status.OK);
            // far more rows than the way can hold: a cross join, 10^10 rows, cut at --max-rows
            codec.write(out, new IncomingServerMessage(Header.request(2, db, "SELECT a.n, b.label FROM wide a, wide b",
                    Priority.NORMAL)));
            OutgoingServerMessage first = until(codec, in, 2);
            assertThat(TablePages.isPage(first.footer())).as(first.footer().replyText()).isTrue();
            int got = ((TableResult) first.footer().result()).rows().size();
            Thread.sleep(2_000); // not reading: the socket fills, the server holds its two pages, the query waits
            codec.write(out, new IncomingServerMessage(Header.request(3, "", "?cancel 2", Priority.URGENT)));
            OutgoingServerMessage last;
            do {
                last = until(codec, in, 2);
                if (TablePages.isPage(last.footer())) {
                    got += ((TableResult) last.footer().result()).rows().size();
                }
            } while (!last.status().isFinal());
            assertThat(last.footer().errorCode()).as(last.footer().replyText()).isEqualTo(ErrorCode.CANCELLED);
            assertThat(got).as("rows that reached the client before the cancel").isLessThan(1_000_000);
            System.out.println("cancelled after " + got + " rows had reached the client");
        }
    }

    /** The next reply to message {@code id}, skipping others (the cancel's own answer, pushes). */
    private static OutgoingServerMessage until(FrameCodec codec, DataInputStream in, long id) throws Exception {
        while (true) {
            OutgoingServerMessage m = (OutgoingServerMessage) codec.read(in);
            if (m.header().messageId() == id) {
                return m;
            }
        }
    }

    /**
     * Alice's session, once the server has read the permit file the test wrote. A connection that
     * has not logged in within the server's login deadline (10 s, which a loaded machine can use up
     * between refusals) is closed by the server: then a new one.
     */
    private static ClientSocketHandler loginWhenThePermitFileIsRead(int port) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (true) {
            ClientSocketHandler c = ClientSocketHandler.connectPlain("localhost", port);
            try {
                c.login("alice", TestSystem.PASSWORD.toCharArray());
                return c;
            } catch (org.ripv.client.handlers.RipvErrorException | java.io.IOException e) {
                c.close();
                assertThat(System.nanoTime()).as("logged in: " + e.getMessage()).isLessThan(end);
                Thread.sleep(300);
            }
        }
    }

    private String awaitDatabase(ClientSocketHandler c, Process service) throws Exception {
        long end = System.nanoTime() + T.toNanos();
        while (true) {
            MailboxList boxes = (MailboxList) c.call("", "?mailboxes", Priority.NORMAL, T, null).footer().result();
            for (MailboxStatus b : boxes.mailboxes()) {
                if (b.address().startsWith("<DatabaseServer>")) {
                    return b.address();
                }
            }
            assertThat(service.isAlive()).as(sys.log("database")).isTrue();
            assertThat(System.nanoTime()).as("the DatabaseServer registered: " + sys.log("database")).isLessThan(end);
            Thread.sleep(300);
        }
    }

    /** 100,000 rows of 400 characters, made by doubling: a few statements, not 100,000. */
    private static void setUp(ClientSocketHandler c, String db) throws Exception {
        sql(c, db, "CREATE TABLE wide (n INT PRIMARY KEY, label VARCHAR(420))");
        sql(c, db, "INSERT INTO wide VALUES (1, '1" + PAD + "')");
        for (int have = 1; have < ROWS; have *= 2) {
            sql(c, db, "INSERT INTO wide SELECT n + " + have + ", TRIM(CHAR(n + " + have + ")) || '" + PAD
                    + "' FROM wide WHERE n + " + have + " <= " + ROWS);
        }
    }

    private static void sql(ClientSocketHandler c, String db, String sql) throws Exception {
        OutgoingServerMessage r = c.call(db, sql, Priority.NORMAL, T, null);
        assertThat(r.status()).as(sql + ": " + r.footer().replyText()).isEqualTo(Status.OK);
    }
}
