package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.it.InJvmCli;
import org.ripv.testing.LoopbackSshd;

/**
 * Issue 37 item 4 as launched: {@code ripv-server.jar}, and {@code ripv-services.jar} as the
 * SerialPortServer (a {@code listen://} link), the DatabaseServer with a DAC deployment
 * ({@code --dac}) whose destination is Debian's OpenSSH on a loopback port (started by the test,
 * key authentication, known_hosts checked), and the glider simulator, which calls in carrying
 * rosie_713's {@code .sbd}/{@code .tbd} and their sensor-list caches. The workflow queued for its
 * call fetches them; the server ingests each as it lands, the deployment makes the profiles,
 * checks and pushes them, and the test reads them back from the SFTP server's folder (ncdump,
 * python3-netCDF4) and asks {@code ?dac MAILBOX}. A deployment with bad metadata keeps the
 * DatabaseServer from starting, with the reason.
 */
class DacDeliveryEndToEndTest {
    static final Path ROOT = LaunchedSystem.ROOT;
    static final Path SHARED = ROOT.resolve("../shared/data/slocum-binary").normalize();
    static final String SEG = "rosie_713-2019-166-0-157";

    @TempDir
    Path tmp;

    @RegisterExtension
    final LaunchedSystem sys = new LaunchedSystem("-Dripv.host=localhost");

    List<String> nc(Path dir) throws Exception {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".nc")).sorted().toList();
        }
    }

    static String run(Path dir, String... cmd) throws Exception {
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).start();
        String s = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(String.join(" ", cmd) + ": " + s).isZero();
        return s;
    }

    Path deployment(Path dir, LoopbackSshd sshd, String metadata) throws Exception {
        Path f = dir.resolve("deployment.json");
        Files.writeString(f, "{\"glider\": \"rosie_713\", \"metadata\": \"" + metadata + "\", \"qc\": \""
                + ROOT.resolve("docs/samples/dac-qc.yml") + "\", \"folder\": \"" + dir.resolve("dac") + "\", \"destination\": \""
                + sshd.url() + "\", \"key\": \"" + sshd.key() + "\", \"known_hosts\": \"" + sshd.knownHosts()
                + "\", \"first_retry_seconds\": 1}");
        return f;
    }

    @Test
    void aCallsSlocumFilesEndAsProfilesOnTheDacsSftpServer() throws Exception {
        LaunchedSystem.assumeJars();
        assumeTrue(Files.isDirectory(SHARED.resolve("realtime_raw")), "needs ../shared/data/slocum-binary beside the repository");
        try (LoopbackSshd sshd = LoopbackSshd.start(Files.createDirectories(tmp.resolve("sshd")))) {
            Path glider = Files.createDirectories(tmp.resolve("glider-files"));
            for (String f : List.of(SEG + ".sbd", SEG + ".tbd")) {
                Files.copy(SHARED.resolve("realtime_raw").resolve(f), glider.resolve(f));
            }
            for (String c : List.of("6b016a2e.cac", "426bd56d.cac")) {
                Files.copy(SHARED.resolve("cac").resolve(c), glider.resolve(c));
            }
            sys.startServer(List.of());

            // bad metadata: the DatabaseServer refuses to start, saying why, and writes nothing
            Path badDir = Files.createDirectories(tmp.resolve("bad"));
            Path badMeta = badDir.resolve("meta.json");
            Files.writeString(badMeta, Files.readString(ROOT.resolve("docs/samples/dac-deployment.json"))
                    .replace("\"wmo_id\": \"4802989\"", "\"wmo_id\": 4802989"));
            Process bad = sys.startService("bad-database", List.of(), "database", "--data", tmp.resolve("bad-db").toString(),
                    "--dac", deployment(badDir, sshd, badMeta.toString()).toString());
            assertThat(bad.waitFor(120, TimeUnit.SECONDS)).isTrue();
            assertThat(bad.exitValue()).as(sys.log("bad-database")).isEqualTo(1);
            assertThat(sys.log("bad-database")).contains("the DAC deployment is refused")
                    .contains("wmo_id must be a string, found number 4802989");
            assertThat(badDir.resolve("dac")).doesNotExist();

            Path dacDir = Files.createDirectories(tmp.resolve("deployment"));
            sys.startService("serial", List.of(), "serial", "--link", "listen://127.0.0.1:" + sys.gliderPort + ",name=rosie",
                    "--carrier", "ignore", "--no-enumerate");
            sys.startService("database", List.of(), "database", "--data", tmp.resolve("db").toString(),
                    "--dac", deployment(dacDir, sshd, ROOT.resolve("docs/samples/dac-deployment.json").toString()).toString());
            String box = "<SerialPortServer>::<localhost>rosie";
            String db = "<DatabaseServer>::<localhost>TTY1";
            sys.awaitMailboxes(box, db);
            assertThat(sys.log("database")).contains("DAC deployment of rosie_713 -> " + sshd.url());
            assertThat(sys.cli("?dac " + db)).as(sys.out()).isZero();
            assertThat(sys.out()).contains("rosie_713 → " + sshd.url() + ": 0 profiles; no profile yet");

            // the glider's next call fetches its files: the caches first, then the segment's pair
            Path wf = tmp.resolve("fetch-dac.wf");
            Files.writeString(wf, "workflow once\nymodem:get *.cac\nymodem:get *.sbd *.tbd\n");
            assertThat(sys.cli("put " + wf, "?queue add " + box + " fetch-dac.wf")).as(sys.out()).isZero();
            sys.startSimulator("--call", "127.0.0.1:" + sys.gliderPort, "--name", "rosie", "--dive-seconds", "600",
                    "--surface-seconds", "120", "--dir", tmp.resolve("glider").toString(), "--files", glider.toString());

            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(240);
            while (nc(sshd.drop()).size() < 10) {
                assertThat(System.nanoTime()).as("ten profiles on the SFTP server; ?dac: " + (sys.cli("?dac " + db) >= 0 ? sys.out() : "")
                        + "\ndatabase log: " + sys.log("database") + "\nserial log: " + sys.log("serial")).isLessThan(end);
                Thread.sleep(500);
            }
            List<String> sent = nc(sshd.drop());
            assertThat(sent).hasSize(10).allMatch(n -> n.matches("rosie_713_20190620T\\d{6}Z_rt\\.nc"));
            assertThat(sent).contains("rosie_713_20190620T063600Z_rt.nc");
            try (Stream<Path> s = Files.list(sshd.drop())) {
                assertThat(s.map(x -> x.getFileName().toString()).filter(n -> n.endsWith(".part"))).isEmpty();
            }
            // read back as the DAC would: ncdump, and Debian's python3 with netCDF4
            Path one = sshd.drop().resolve("rosie_713_20190620T063600Z_rt.nc");
            assertThat(run(tmp, "ncdump", "-h", one.toString())).contains("time = UNLIMITED ; // (21 currently)")
                    .contains("int profile_id").contains("qartod_temperature_primary_flag").contains(":wmo_id = \"4802989\"");
            Path python = Path.of("/usr/bin/python3");
            if (Files.isExecutable(python) && new ProcessBuilder(python.toString(), "-c", "import netCDF4").start().waitFor() == 0) {
                String py = run(tmp, python.toString(), "-c", String.join("\n",
                        "import netCDF4, sys",
                        "d = netCDF4.Dataset(sys.argv[1])",
                        "p = d['pressure'][:]",
                        "print(d.data_model, len(d.dimensions['time']), round(float(p.max()), 1), round(float(p.min()), 1),",
                        "      d['platform'].getncattr('id'), int(d['profile_id'][...]))"), one.toString());
                assertThat(py.strip()).startsWith("NETCDF3_CLASSIC 21 141.5 11.9 rosie_713 ");
            }
            // the pilot's view of the delivery
            assertThat(sys.cli("?dac " + db)).as(sys.out()).isZero();
            assertThat(sys.out()).contains("rosie_713 → " + sshd.url() + ": 10 profiles (10 sent)")
                    .contains("rosie_713_20190620T063600Z_rt.nc  real-time climb, 21 samples, 11.9 to 141.5 dbar, QC temperature 20 good 1 suspect")
                    .containsPattern("newest profile rosie_713_20190620T080055Z_rt\\.nc, its data \\d+ days ago");
            ByteArrayOutputStream jsonOut = new ByteArrayOutputStream();
            assertThat(InJvmCli.exec(jsonOut, jsonOut, InJvmCli.as("alice", "localhost:" + sys.clientPort,
                    "--known-hosts", sys.knownHosts.toString(), "--json"), "?dac " + db + " --json"))
                    .as(jsonOut.toString(StandardCharsets.UTF_8)).isZero();
            com.fasterxml.jackson.databind.ObjectMapper m = new com.fasterxml.jackson.databind.ObjectMapper();
            String text = null;
            for (String line : jsonOut.toString(StandardCharsets.UTF_8).split("\n")) {
                if (line.startsWith("{")) {
                    text = m.readTree(line).path("text").asText(null);
                }
            }
            assertThat(text).as(jsonOut.toString(StandardCharsets.UTF_8)).isNotNull();
            @SuppressWarnings("unchecked")
            Map<String, Object> state = (Map<String, Object>) m.readValue(text, List.class).get(0);
            assertThat(state).containsEntry("glider", "rosie_713").containsEntry("counts", Map.of("sent", 10));
            assertThat(((Number) state.get("seconds_since_newest_profile")).longValue()).isGreaterThan(0);
            // usage errors and an unknown glider: refused with the reason, the service keeps answering
            assertThat(sys.cli("?dac")).isNotZero();
            assertThat(sys.out()).contains("usage: ?dac MAILBOX [GLIDER] [--json]");
            assertThat(sys.cli("?dac " + db + " nobody")).isNotZero();
            assertThat(sys.out()).contains("no DAC deployment of nobody here");
            assertThat(sys.cli("?dac " + db + " rosie_713")).as(sys.out()).isZero();
            assertThat(sys.out()).contains("10 profiles (10 sent)");
            // every file once in the ledger, sent
            assertThat(Files.readAllLines(dacDir.resolve("dac/dac-ledger.tsv")).stream().filter(l -> l.contains("\tsent\t")))
                    .hasSize(10);
        }
    }
}
