package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.server.files.FileStore;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 34: a file a vehicle's call fetched goes on to the DatabaseServer from the SerialPortServer
 * that fetched it, by a one-use ticket the server signed (org.ripv.handout): the server relays
 * none of its bytes and never reads its own copy back (its download directory's bytes-read count
 * stays where it was), while the user's own {@code ?download} still reads the stored copy. A
 * SerialPortServer the DatabaseServer cannot reach (outbound-only) gets the old relay, with the
 * same verdict. HandoutEndToEndTest measures the same with launched jars.
 */
class IngestWithoutReadBackTest {
    static final Path SHARED = Path.of("../ripv-services/src/test/resources/slocum");
    static final String DB = "<DatabaseServer>::<localhost>TTY1";

    @TempDir
    Path dir;
    final ByteArrayOutputStream out = new ByteArrayOutputStream();

    @Test
    void theFetchedBytesReachTheDatabaseWithoutTheServerReadingThemBack() throws Exception {
        try (GliderSimulator glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), SerialEndToEndTest.YMODEM)) {
            Files.copy(SHARED.resolve("cp_388_2016_012_0_0.mrg"), glider.directory().resolve("cp_388_2016_012_0_0.mrg"));
            int port = glider.listen(0);
            try (TestSystem sys = TestSystem.start(dir.resolve("sys"))) {
                sys.user("alice", "operators");
                LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + port).withIdleTimeout(Duration.ofSeconds(1))
                        .withReconnectEvery(Duration.ofMillis(300)).withYmodem(SerialEndToEndTest.YMODEM);
                SerialPortServer s = new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("work"));
                sys.register(s);
                String serial = "<SerialPortServer>::<localhost>" + s.handles().get(0);
                sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                        QueryLimits.defaults()));
                FileStore files = sys.server().fileStore();
                long before = files.downloadBytesRead();

                assertThat(cli(sys, "use " + serial, "ymodem:get cp_388_2016_012_0_0.mrg")).as(out()).isZero();
                assertThat(out()).contains("fetched 1, ingested 1 into " + DB).contains("2 positions");
                String stored = FileStore.folderFor(serial) + "/cp_388_2016_012_0_0.mrg";
                long size = Files.size(sys.downloadDir().resolve(stored));
                assertThat(files.downloadBytesRead()).as("bytes read back from the download directory for the ingest")
                        .isEqualTo(before);
                assertThat(sys.server().dataLoop().bytesRelayed()).as("bytes the server relayed to the DatabaseServer: it"
                        + " read them from the SerialPortServer by ticket").isZero();
                assertThat(cli(sys, "use " + DB, "SELECT COUNT(*) FROM positions")).as(out()).isZero();
                assertThat(out()).containsPattern("(?m)^\\s*2\\s*$");

                // the count is real: the user's own download reads the stored copy, every byte of it
                Path local = Files.createDirectories(dir.resolve("got"));
                assertThat(cli(sys, "get " + stored + " " + local)).as(out()).isZero();
                assertThat(out()).contains("(" + size + " bytes)");
                assertThat(files.downloadBytesRead()).isEqualTo(before + size);
            }
        }
    }

    /**
     * A SerialPortServer behind NAT (outbound-only) cannot be reached by the DatabaseServer: the
     * server relays the bytes its reply brought, and the user sees the same verdict.
     */
    @Test
    void fromAServiceOutOfReachTheServerRelaysTheBytes() throws Exception {
        try (GliderSimulator glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), SerialEndToEndTest.YMODEM)) {
            Files.copy(SHARED.resolve("cp_388_2016_012_0_0.mrg"), glider.directory().resolve("cp_388_2016_012_0_0.mrg"));
            int port = glider.listen(0);
            try (TestSystem sys = TestSystem.start(dir.resolve("sys"))) {
                sys.user("alice", "operators");
                int outbound = sys.server().openOutbound(0);
                LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + port).withIdleTimeout(Duration.ofSeconds(1))
                        .withReconnectEvery(Duration.ofMillis(300)).withYmodem(SerialEndToEndTest.YMODEM);
                SerialPortServer s = new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("work"));
                ServiceOptions o = sys.serviceOptions();
                ServiceConnector c = ServiceConnector.connect(s, new ServiceOptions(o.serverHost(), o.registryPort(), sys.secret(),
                        0, o.heartbeat()).outboundOnly(outbound));
                try {
                    assertThat(c.awaitRegistered(Duration.ofSeconds(20))).isTrue();
                    String serial = "<SerialPortServer>::<localhost>" + s.handles().get(0);
                    sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                            QueryLimits.defaults()));

                    assertThat(cli(sys, "use " + serial, "ymodem:get cp_388_2016_012_0_0.mrg")).as(out()).isZero();
                    assertThat(out()).contains("fetched 1, ingested 1 into " + DB).contains("2 positions");
                    long size = Files.size(SHARED.resolve("cp_388_2016_012_0_0.mrg"));
                    assertThat(sys.server().dataLoop().bytesRelayed()).as("relayed through the server").isEqualTo(size);
                    assertThat(cli(sys, "use " + DB, "SELECT COUNT(*) FROM positions")).as(out()).isZero();
                    assertThat(out()).containsPattern("(?m)^\\s*2\\s*$");
                } finally {
                    c.close();
                    s.stop();
                }
            }
        }
    }

    int cli(TestSystem sys, String... lines) {
        return InJvmCli.exec(out, out, InJvmCli.as("alice", "localhost:" + sys.server().port(), "--timeout", "120"), lines);
    }

    String out() {
        return out.toString(StandardCharsets.UTF_8);
    }
}
