package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import net.jpountz.lz4.LZ4Compressor;
import net.jpountz.lz4.LZ4Factory;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.ServerConfig;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.ingest.IngestLimits;
import org.ripv.services.ingest.SlocumEncoder;
import org.ripv.services.ingest.SlocumSensor;

/**
 * Issue 33 item 8: a 100 KB {@code .scd} decompressed to 12.6 million cycles; ingest had no size
 * or row limit, wrote one transaction, and the DatabaseServer's MailBox stayed busy for minutes
 * with no {@code ?cancel} reaching it. Now the operator's limits ({@code --ingest-max-bytes},
 * {@code --ingest-max-rows}) refuse such a file with nothing stored, and {@code ?cancel} stops an
 * ingest under way, rolling its file back.
 */
class Lz4BombAttackTest {
    static final Duration T = Duration.ofSeconds(120);
    static final String DB = "<DatabaseServer>::<localhost>TTY1";

    @TempDir
    static Path dir;
    static TestSystem sys;

    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config).user("otto", "operators");
        // The operator's limits: 8 MiB decompressed, 200,000 rows a file.
        sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                QueryLimits.defaults()).withIngestLimits(new IngestLimits(8L << 20, 200_000)));
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    /** A compressed file of {@code cycles} cycles, the values changing each cycle so each is stored. */
    static byte[] scd(String name, int cycles) throws Exception {
        return scd(name, cycles, 0);
    }

    /** As above with {@code wide} more 8-byte sensors, each changing every cycle: many plain bytes a cycle. */
    static byte[] scd(String name, int cycles, int wide) throws Exception {
        ByteArrayOutputStream plain = new ByteArrayOutputStream();
        Map<String, String> tags = new LinkedHashMap<>();
        tags.put("full_filename", name);
        tags.put("filename_extension", "sbd");
        List<SlocumSensor> sensors = new java.util.ArrayList<>(List.of(new SlocumSensor("m_present_time", "timestamp", 8),
                new SlocumSensor("m_depth", "m", 4)));
        for (int k = 0; k < wide; k++) {
            sensors.add(new SlocumSensor("x_wide_" + k, "nodim", 8));
        }
        SlocumEncoder e = SlocumEncoder.start(plain, tags, sensors);
        double[] row = new double[sensors.size()];
        for (int i = 0; i < cycles; i++) {
            row[0] = 1.56e9 + i;
            for (int k = 1; k < row.length; k++) {
                row[k] = i % 2;
            }
            e.cycle(row);
        }
        e.end();
        byte[] p = plain.toByteArray();
        LZ4Compressor lz4 = LZ4Factory.fastestJavaInstance().highCompressor();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] block = new byte[lz4.maxCompressedLength(65_536)];
        for (int at = 0; at < p.length; at += 65_536) {
            int n = lz4.compress(p, at, Math.min(65_536, p.length - at), block, 0, block.length);
            out.write(n >> 8);
            out.write(n & 0xff);
            out.write(block, 0, n);
        }
        return out.toByteArray();
    }

    static OutgoingServerMessage ingest(ClientSocketHandler c, String name, byte[] data) throws Exception {
        Files.write(sys.downloadDir().resolve(name), data);
        return c.call(DB, "ingest " + name, Priority.NORMAL, T, p -> { });
    }

    static long rows(ClientSocketHandler c, String file) throws Exception {
        OutgoingServerMessage r = c.call(DB, "SELECT COUNT(*) FROM data_file WHERE name LIKE '" + file + "%'", Priority.NORMAL, T, p -> { });
        return Long.parseLong(((org.ripv.messages.TableResult) r.footer().result()).rows().get(0)[0]);
    }

    @Test
    void aBombIsRefusedWithTheLimitAndNothingStored() throws Exception {
        ClientSocketHandler otto = sys.login("otto");
        byte[] bytesBomb = scd("bomb_a-2019-001-0-0", 20_000, 100); // ~16 MB decompressed in 20,000 rows
        assertThat(bytesBomb.length).as("a small file").isLessThan(1 << 20);
        OutgoingServerMessage r = ingest(otto, "bomb_a-2019-001-0-0.scd", bytesBomb);
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().replyText()).contains("refused, nothing stored").contains("decompresses to more than 8388608 bytes")
                .contains("--ingest-max-bytes");
        OutgoingServerMessage rows = ingest(otto, "bomb_b-2019-001-0-0.scd", scd("bomb_b-2019-001-0-0", 250_000));
        assertThat(rows.footer().replyText()).contains("refused, nothing stored").contains("more than 200000 rows")
                .contains("--ingest-max-rows");
        assertThat(rows(otto, "bomb_")).as("nothing of either file stored").isZero();
        otto.close();
    }

    @Test
    void cancelStopsAnIngestUnderWay() throws Exception {
        ClientSocketHandler otto = sys.login("otto");
        Files.write(sys.downloadDir().resolve("long_a-2019-001-0-0.scd"), scd("long_a-2019-001-0-0", 190_000));
        long id = otto.nextId();
        CompletableFuture<OutgoingServerMessage> running = otto.send(Header.request(id, DB, "ingest long_a-2019-001-0-0.scd",
                Priority.NORMAL), p -> { });
        long end = System.nanoTime() + T.toNanos();
        while (!otto.call("", "?status " + DB, Priority.NORMAL, T, p -> { }).footer().replyText().contains("busy")) {
            assertThat(System.nanoTime()).as("the ingest starts").isLessThan(end);
            Thread.sleep(20);
        }
        Thread.sleep(500);
        long t0 = System.nanoTime();
        OutgoingServerMessage cancel = otto.call("", "?cancel " + id, Priority.NORMAL, T, p -> { });
        assertThat(cancel.status()).as(cancel.footer().replyText()).isEqualTo(Status.OK);
        OutgoingServerMessage r = running.get(T.toSeconds(), TimeUnit.SECONDS);
        assertThat(Duration.ofNanos(System.nanoTime() - t0)).as("stopped within seconds").isLessThan(Duration.ofSeconds(20));
        assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.CANCELLED);
        assertThat(r.footer().replyText()).contains("cancelled after").contains("nothing of it stored");
        assertThat(rows(otto, "long_a")).isZero();
        // The MailBox serves the next command at once.
        assertThat(otto.call(DB, "VALUES (1)", Priority.NORMAL, T, p -> { }).status()).isEqualTo(Status.OK);
        otto.close();
    }
}
