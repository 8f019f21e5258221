package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.services.ingest.DbaFiles;

/**
 * {@code ingest NAME...} on the embedded Derby database, in-process: counts against an
 * independent count of the shared files, the views, a file stored once under two names, and
 * refused files storing nothing.
 */
class IngestTest {
    @TempDir
    static Path data;
    private static DatabaseServer service;
    private static final BlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
    private static final AtomicLong ids = new AtomicLong();
    private static ServiceHarness sql;

    @BeforeAll
    static void start() throws Exception {
        service = new DatabaseServer("testhost", List.of(EmbeddedDatabase.prepare(data, "TTY1")), QueryLimits.defaults());
        service.start();
        sql = new ServiceHarness(service);
    }

    @AfterAll
    static void stop() {
        if (service != null) {
            service.stop();
        }
    }

    /** Sends {@code ingest} with the named files attached as the server does. */
    static OutgoingServiceMessage ingest(List<String> roles, Attachment... files) throws InterruptedException {
        StringBuilder cmd = new StringBuilder("ingest");
        for (Attachment a : files) {
            cmd.append(' ').append(a.name());
        }
        long id = ids.incrementAndGet() + 1_000_000;
        BlockingQueue<OutgoingServiceMessage> mine = new LinkedBlockingQueue<>();
        service.replyTo(mine::add);
        service.accept(new IncomingServiceMessage(new Header(id, new IdBadge("123456", "alice"), roles,
                service.name().toString(), service.name().mailbox("TTY1").toString(), cmd.toString(), Priority.NORMAL,
                Attachment.bundle(List.of(files)))));
        try {
            while (true) {
                OutgoingServiceMessage r = mine.poll(120, TimeUnit.SECONDS);
                assertThat(r).isNotNull();
                if (r.status().isFinal()) {
                    return r;
                }
            }
        } finally {
            sql = new ServiceHarness(service);
        }
    }

    static OutgoingServiceMessage ingest(Attachment... files) throws InterruptedException {
        return ingest(List.of(DatabaseHandler.OPERATORS_ROLE), files);
    }

    static Attachment shared(String storeName, String file) {
        return new Attachment(storeName, DbaFiles.read(DbaFiles.shared(file)));
    }

    static long count(String query) throws InterruptedException {
        OutgoingServiceMessage r = sql.send("TTY1", query);
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        return Long.parseLong(((TableResult) r.footer().result()).rows().get(0)[0]);
    }

    static TableResult table(String query) throws InterruptedException {
        OutgoingServiceMessage r = sql.send("TTY1", query);
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        return (TableResult) r.footer().result();
    }

    @Test
    void theSharedFilesGoInWithTheirIndependentCountsAndTheViewsShowThem() throws Exception {
        DbaFiles.Count cp = DbaFiles.count(DbaFiles.read(DbaFiles.shared("cp_388_2016_012_0_0.mrg")));
        OutgoingServiceMessage r = ingest(shared("cp_388_2016_012_0_0.mrg", "cp_388_2016_012_0_0.mrg"));
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(r.footer().replyText()).startsWith("cp_388-2016-012-0-0: 23 rows, 52 sensors, " + cp.values()
                + " values, 2 positions");
        long file = count("SELECT file_id FROM data_file WHERE name = 'cp_388_2016_012_0_0.mrg'");
        assertThat(count("SELECT COUNT(*) FROM reading WHERE file_id = " + file)).isEqualTo(cp.values());
        assertThat(count("SELECT COUNT(*) FROM positions WHERE vehicle = 'cp_388'")).isEqualTo(cp.positionRows()).isEqualTo(2);
        TableResult pos = table("SELECT lat, lon, source, time_utc FROM positions WHERE vehicle = 'cp_388' ORDER BY time_utc");
        assertThat(Double.parseDouble(pos.rows().get(0)[0])).isCloseTo(39.84772, within(1e-5));
        assertThat(Double.parseDouble(pos.rows().get(0)[1])).isCloseTo(-70.77226, within(1e-5));
        assertThat(pos.rows().get(0)[2]).isEqualTo("dead-reckoned");
        assertThat(pos.rows().get(0)[3]).startsWith("2016-01-13 17:20:11.24"); // 1452705611.24094 UTC
        // no-fix GPS values are not stored at all
        assertThat(count("SELECT COUNT(*) FROM reading r JOIN sensor_def s ON s.sensor_id = r.sensor_id"
                + " WHERE s.name = 'm_gps_lat' AND r.file_id = " + file)).isZero();

        DbaFiles.Count unit = DbaFiles.count(DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg")));
        r = ingest(shared("unit_363.mrg", "unit_363_2013_245_6_6.mrg"));
        assertThat(r.footer().replyText()).isEqualTo("unit_363-2013-245-6-6: 657 rows, 29 sensors, " + unit.values()
                + " values, " + unit.positionRows() + " positions" + (unit.noFix() > 0 ? " (" + unit.noFix()
                + " no-fix values left out)" : ""));
        assertThat(count("SELECT COUNT(*) FROM positions WHERE vehicle = 'unit_363'")).isEqualTo(unit.positionRows());
        assertThat(count("SELECT COUNT(*) FROM positions WHERE vehicle = 'unit_363' AND source = 'gps'")).isPositive();
        assertThat(count("SELECT COUNT(*) FROM positions WHERE (lat < 50 OR lat > 50.5 OR lon > -144 OR lon < -145)"
                + " AND vehicle = 'unit_363'")).isZero();
        // latest: one row per sensor with a value; m_depth's last value is the file's last m_depth
        assertThat(count("SELECT COUNT(*) FROM latest WHERE vehicle = 'unit_363'")).isEqualTo(29);
        String[] lines = new String(DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg")), StandardCharsets.US_ASCII)
                .split("\n");
        int depthCol = List.of(lines[14].trim().split(" ")).indexOf("m_depth");
        String lastDepth = null;
        for (int i = 17; i < lines.length; i++) {
            String cell = lines[i].trim().split(" ")[depthCol];
            lastDepth = cell.equals("NaN") ? lastDepth : cell;
        }
        TableResult latestDepth = table("SELECT value FROM latest WHERE vehicle = 'unit_363' AND sensor = 'm_depth'");
        assertThat(Double.parseDouble(latestDepth.rows().get(0)[0])).isEqualTo(Double.parseDouble(lastDepth));
        assertThat(count("SELECT COUNT(*) FROM dives WHERE vehicle = 'unit_363' AND max_depth > 900")).isEqualTo(1);
        // the read-only user sees the new views too
        OutgoingServiceMessage asReader = sql.send("TTY1", "SELECT COUNT(*) FROM positions", "bob",
                List.of(DatabaseHandler.READER_ROLE));
        assertThat(asReader.status()).as(asReader.footer().replyText()).isEqualTo(Status.OK);
        OutgoingServiceMessage readerIngest = ingest(List.of(DatabaseHandler.READER_ROLE), shared("x.mrg", "cp_388_2016_012_0_0.mrg"));
        assertThat(readerIngest.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
    }

    @Test
    void theSameFileUnderTwoNamesIsStoredOnce() throws Exception {
        byte[] file = DbaFiles.generate("twice", 12, 30, 9);
        OutgoingServiceMessage r = ingest(new Attachment("a.mrg", file), new Attachment("b.mrg", file));
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(r.footer().replyText()).contains("twice-2024-100-1-0: 30 rows, 12 sensors")
                .contains("twice-2024-100-1-0: stored already");
        assertThat(count("SELECT COUNT(*) FROM data_file WHERE vehicle = 'twice'")).isEqualTo(1);
        r = ingest(new Attachment("c.dba", file));
        assertThat(r.footer().replyText()).contains("stored already");
        assertThat(count("SELECT COUNT(*) FROM data_file WHERE vehicle = 'twice'")).isEqualTo(1);
    }

    @Test
    void aFiveThousandSensorFileIsStoredWhole() throws Exception {
        byte[] file = DbaFiles.generate("wide", 5000, 20, 21);
        DbaFiles.Count c = DbaFiles.count(file);
        OutgoingServiceMessage r = ingest(new Attachment("wide.mrg", file));
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(r.footer().replyText()).isEqualTo("wide-2024-100-1-0: 20 rows, 5000 sensors, " + c.values() + " values, "
                + c.positionRows() + " positions");
        assertThat(count("SELECT COUNT(*) FROM reading r JOIN data_file f ON f.file_id = r.file_id WHERE f.vehicle = 'wide'"))
                .isEqualTo(c.values());
        assertThat(count("SELECT COUNT(*) FROM latest WHERE vehicle = 'wide'")).isEqualTo(5000);
    }

    @Test
    void refusedFilesStoreNothing() throws Exception {
        long files = count("SELECT COUNT(*) FROM data_file");
        long readings = count("SELECT COUNT(*) FROM reading");
        OutgoingServiceMessage r = ingest(shared("short_header.mrg", "short_header.mrg"));
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().replyText()).isEqualTo("short_header.mrg: refused, nothing stored: line 11: the file ends"
                + " in the header after 10 of 14 tag lines");
        // a bad row far down, after several batches went to the database: all rolled back
        String good = new String(DbaFiles.generate("badrow", 30, 3000, 4), StandardCharsets.US_ASCII);
        int cut = good.lastIndexOf(" \n", good.length() - 3);
        String bad = good.substring(0, cut) + " 7 \n";
        r = ingest(new Attachment("badrow.mrg", bad.getBytes(StandardCharsets.US_ASCII)));
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().replyText()).contains("line 3016: the row has more values than the 30 sensors");
        byte[] garbage = new byte[10 << 20];
        new java.util.Random(3).nextBytes(garbage);
        r = ingest(new Attachment("garbage.mrg", garbage));
        assertThat(r.footer().replyText()).startsWith("garbage.mrg: refused, nothing stored: line 1: not a DBA file");
        assertThat(count("SELECT COUNT(*) FROM data_file")).isEqualTo(files);
        assertThat(count("SELECT COUNT(*) FROM reading")).isEqualTo(readings);
        assertThat(count("SELECT COUNT(*) FROM data_file WHERE vehicle = 'badrow'")).isZero();
        // and the service keeps serving
        assertThat(count("SELECT COUNT(*) FROM mission")).isEqualTo(4);
    }
}
