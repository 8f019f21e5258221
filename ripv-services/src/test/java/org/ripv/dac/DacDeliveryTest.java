package org.ripv.dac;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.dac.delivery.Deliveries;
import org.ripv.dac.delivery.Delivery;
import org.ripv.services.ingest.SensorListCache;
import org.ripv.testing.LoopbackSshd;
import org.ripv.testing.LoopbackVsftpd;

/**
 * Delivery on arrival (docs/dac.md#delivery-on-arrival): a deployment given the files as the
 * ingest hands them over writes each profile once, checks it and pushes it — to Debian's OpenSSH
 * and to vsftpd's FTPS, each started by the test on a loopback port — and its state says what
 * happened; bad input and a destination that is down leave it running.
 */
class DacDeliveryTest {
    static final String SEG = DacBadInputTest.SEG;

    static Path deployment(Path dir, String destination, String... more) throws Exception {
        Path f = dir.resolve("deployment.json");
        StringBuilder b = new StringBuilder("{\"glider\": \"rosie_713\", \"metadata\": \"" + DacFixtures.meta() + "\", \"qc\": \""
                + DacFixtures.qc() + "\", \"folder\": \"" + dir.resolve("dac") + "\", \"destination\": \"" + destination + "\"");
        for (int i = 0; i < more.length; i += 2) {
            b.append(", \"").append(more[i]).append("\": ").append(more[i + 1].matches("\\d+") ? more[i + 1] : "\"" + more[i + 1] + "\"");
        }
        Files.writeString(f, b.append("}").toString());
        return f;
    }

    static void arrive(Deliveries d, Path file) throws Exception {
        d.arrived(file.getFileName().toString(), Files.readAllBytes(file), new SensorListCache(DacFixtures.cache()));
    }

    static void settle(Deliveries d) throws InterruptedException {
        for (Delivery x : d.all()) {
            x.settle(120_000);
        }
    }

    static List<String> names(Path dir) throws Exception {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aCallsFilesArePushedOnceOverSftpAndTheDelayedModeReplacesThem(@TempDir Path dir, @TempDir Path ssh, @TempDir Path in)
            throws Exception {
        try (LoopbackSshd sshd = LoopbackSshd.start(ssh);
             Deliveries d = Deliveries.start(List.of(deployment(dir, sshd.url(), "key", sshd.key().toString(),
                     "known_hosts", sshd.knownHosts().toString(), "first_retry_seconds", "1")))) {
            // the science file first: it waits for its flight file
            arrive(d, DacFixtures.raw(SEG + ".tbd"));
            settle(d);
            assertThat(d.status(List.of())).contains(SEG + ": waiting: its flight file (sbd/scd) has not come");
            assertThat(names(sshd.drop())).isEmpty();
            arrive(d, DacFixtures.raw(SEG + ".sbd"));
            settle(d);
            List<String> sent = names(sshd.drop());
            assertThat(sent).hasSize(10).allMatch(n -> n.matches("rosie_713_2019\\d{4}T\\d{6}Z_rt\\.nc"));
            for (String n : sent) {
                assertThat(Files.readAllBytes(sshd.drop().resolve(n))).isEqualTo(Files.readAllBytes(dir.resolve("dac/profiles/" + n)));
            }
            String text = d.status(List.of());
            assertThat(text).contains("rosie_713 → " + sshd.url() + ": 10 profiles (10 sent)")
                    .contains("newest profile rosie_713_").contains(", QC temperature ").doesNotContain("waiting");
            // the same files again (fetched twice): no profile made again, nothing sent again
            long ledgerLines = Files.readAllLines(dir.resolve("dac/dac-ledger.tsv")).size();
            arrive(d, DacFixtures.raw(SEG + ".sbd"));
            arrive(d, DacFixtures.raw(SEG + ".tbd"));
            settle(d);
            assertThat(Files.readAllLines(dir.resolve("dac/dac-ledger.tsv"))).hasSize((int) ledgerLines);
            assertThat(names(sshd.drop())).isEqualTo(sent);
            // after recovery, the delayed-mode files of the same dive replace the real-time profiles
            SensorListCache cache = new SensorListCache(DacFixtures.cache());
            Path dbd = in.resolve(SEG + ".dbd");
            Path ebd = in.resolve(SEG + ".ebd");
            Files.write(dbd, org.ripv.services.ingest.SlocumEncoder.recode(Files.readAllBytes(DacFixtures.raw(SEG + ".sbd")), cache, "dbd", List.of(), (r, n) -> { }));
            Files.write(ebd, org.ripv.services.ingest.SlocumEncoder.recode(Files.readAllBytes(DacFixtures.raw(SEG + ".tbd")), cache, "ebd", List.of(), (r, n) -> { }));
            arrive(d, ebd);
            arrive(d, dbd);
            settle(d);
            assertThat(names(sshd.drop())).hasSize(20).containsAll(sent.stream().map(n -> n.replace("_rt.nc", "_delayed.nc")).toList());
            assertThat(names(dir.resolve("dac/profiles"))).hasSize(10).allMatch(n -> n.endsWith("_delayed.nc"));
            assertThat(names(dir.resolve("dac/replaced"))).isEqualTo(sent);
            @SuppressWarnings("unchecked")
            Map<String, Object> json = (Map<String, Object>) new com.fasterxml.jackson.databind.ObjectMapper()
                    .readValue(d.status(List.of("--json")), List.class).get(0);
            assertThat(json).containsEntry("glider", "rosie_713").containsEntry("counts", Map.of("sent", 10, "replaced", 10));
            assertThat((List<?>) json.get("profiles")).hasSize(20);
            assertThat(String.valueOf(json.get("newest_profile"))).endsWith("_delayed.nc");
            // the real-time files once more, after the delayed ones: nothing made or sent
            arrive(d, DacFixtures.raw(SEG + ".tbd"));
            arrive(d, DacFixtures.raw(SEG + ".sbd"));
            settle(d);
            assertThat(names(sshd.drop())).hasSize(20);
            assertThat(names(dir.resolve("dac/profiles"))).hasSize(10).allMatch(n -> n.endsWith("_delayed.nc"));
            assertThat(d.status(List.of())).contains(sent.get(0) + "  real-time dive, 24 samples, 0.2 to 141.3 dbar, QC temperature 23 good 1 suspect").contains("replaced (by "
                    + sent.get(0).replace("_rt.nc", "_delayed.nc") + " (the real-time file was sent before))");
        }
    }

    @Test
    void aRealTimeFileArrivingAfterItsDelayedModeOneIsNotMade(@TempDir Path dir, @TempDir Path ssh, @TempDir Path in) throws Exception {
        try (LoopbackSshd sshd = LoopbackSshd.start(ssh);
             Deliveries d = Deliveries.start(List.of(deployment(dir, sshd.url(), "key", sshd.key().toString(),
                     "known_hosts", sshd.knownHosts().toString())))) {
            SensorListCache cache = new SensorListCache(DacFixtures.cache());
            Path dbd = in.resolve(SEG + ".dbd");
            Path ebd = in.resolve(SEG + ".ebd");
            Files.write(dbd, org.ripv.services.ingest.SlocumEncoder.recode(Files.readAllBytes(DacFixtures.raw(SEG + ".sbd")), cache, "dbd", List.of(), (r, n) -> { }));
            Files.write(ebd, org.ripv.services.ingest.SlocumEncoder.recode(Files.readAllBytes(DacFixtures.raw(SEG + ".tbd")), cache, "ebd", List.of(), (r, n) -> { }));
            arrive(d, dbd);
            arrive(d, ebd);
            arrive(d, DacFixtures.raw(SEG + ".sbd"));
            arrive(d, DacFixtures.raw(SEG + ".tbd"));
            settle(d);
            assertThat(names(sshd.drop())).hasSize(10).allMatch(n -> n.endsWith("_delayed.nc"));
            assertThat(d.status(List.of())).contains("10 profiles (10 sent)").doesNotContain("_rt.nc");
        }
    }

    @Test
    void badInputIsRefusedByNameAndTheDeploymentKeepsRunning(@TempDir Path dir, @TempDir Path ssh, @TempDir Path in) throws Exception {
        try (LoopbackSshd sshd = LoopbackSshd.start(ssh);
             Deliveries d = Deliveries.start(List.of(deployment(dir, sshd.url(), "key", sshd.key().toString(),
                     "known_hosts", sshd.knownHosts().toString())))) {
            int temp = DacBadInputTest.column("sci_water_temp");
            int cond = DacBadInputTest.column("sci_water_cond");
            List<Path> nanOnly = DacBadInputTest.edited(Files.createDirectories(in.resolve("nan")), (row, n) -> {
                row[temp] = Double.NaN;
                row[cond] = Double.NaN;
            });
            nanOnly.forEach(f -> call(() -> arrive(d, f)));
            settle(d);
            assertThat(d.status(List.of())).contains(SEG + ": refused: no profile written: " + SEG
                    + ".tbd: the CTD gave no temperature or conductivity");
            int t = DacBadInputTest.column("sci_m_present_time");
            List<Path> back = DacBadInputTest.edited(Files.createDirectories(in.resolve("back")), (row, n) -> {
                if (n > 300) {
                    row[t] -= 3600;
                }
            });
            back.forEach(f -> call(() -> arrive(d, f)));
            settle(d);
            assertThat(d.status(List.of())).contains("the clock steps back at row");
            assertThat(names(dir.resolve("dac/profiles"))).isEmpty();
            assertThat(names(sshd.drop())).isEmpty();
            assertThat(names(dir.resolve("dac")).stream().filter(n -> n.startsWith(".staging"))).isEmpty();
            // a file that is not a Slocum file at all, under a Slocum name
            d.arrived("rosie_713-2019-166-0-158.tbd", new byte[] {1, 2, 3}, new SensorListCache(DacFixtures.cache()));
            d.arrived("rosie_713-2019-166-0-158.sbd", new byte[] {1, 2, 3}, new SensorListCache(DacFixtures.cache()));
            settle(d);
            assertThat(d.status(List.of())).contains("rosie_713-2019-166-0-158: refused");
            // and then a good call: delivered
            arrive(d, DacFixtures.raw(SEG + ".sbd"));
            arrive(d, DacFixtures.raw(SEG + ".tbd"));
            settle(d);
            assertThat(names(sshd.drop())).hasSize(10);
            assertThat(d.status(List.of())).contains("10 profiles (10 sent)").doesNotContain(SEG + ": refused");
        }
    }

    @Test
    void aPushThatFailsIsTriedAgainWithBackOffAndSentOnce(@TempDir Path dir, @TempDir Path ssh) throws Exception {
        try (LoopbackSshd sshd = LoopbackSshd.start(ssh);
             Deliveries d = Deliveries.start(List.of(deployment(dir, sshd.url(), "key", sshd.key().toString(),
                     "known_hosts", sshd.knownHosts().toString(), "first_retry_seconds", "1", "max_retry_seconds", "2")))) {
            sshd.stop();
            arrive(d, DacFixtures.raw(SEG + ".sbd"));
            arrive(d, DacFixtures.raw(SEG + ".tbd"));
            settle(d);
            assertThat(d.status(List.of())).contains("10 push failed").contains("push failed (not sent after 1 attempt: ");
            sshd.resume();
            long deadline = System.nanoTime() + 60_000_000_000L;
            while (!d.status(List.of()).contains("10 profiles (10 sent)") && System.nanoTime() < deadline) {
                Thread.sleep(200);
            }
            assertThat(d.status(List.of())).contains("10 profiles (10 sent)");
            assertThat(names(sshd.drop())).hasSize(10);
            assertThat(Files.readAllLines(dir.resolve("dac/dac-ledger.tsv")).stream().filter(l -> l.contains("\tsent\t"))).hasSize(10);
        }
    }

    @Test
    void ftpsWithThePinnedCertificateDeliversAndAnotherCertificateIsRefused(@TempDir Path dir, @TempDir Path ftp, @TempDir Path other)
            throws Exception {
        try (LoopbackVsftpd vsftpd = LoopbackVsftpd.start(ftp)) {
            Path password = Files.writeString(dir.resolve("password"), "pilot@example.org\n");
            // a certificate that is not the server's: the TLS handshake is refused, nothing sent
            Path stranger = other.resolve("stranger.pem");
            DacFixtures.run(other, "openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "2", "-subj", "/CN=127.0.0.1",
                    "-addext", "subjectAltName=IP:127.0.0.1", "-keyout", other.resolve("k.pem").toString(), "-out", stranger.toString());
            Path wrongDir = Files.createDirectories(dir.resolve("wrong"));
            try (Deliveries d = Deliveries.start(List.of(deployment(wrongDir, vsftpd.url(), "password_file", password.toString(),
                    "trust", stranger.toString(), "first_retry_seconds", "600")))) {
                arrive(d, DacFixtures.raw(SEG + ".sbd"));
                arrive(d, DacFixtures.raw(SEG + ".tbd"));
                settle(d);
                assertThat(d.status(List.of())).contains("10 push failed").containsPattern("push failed \\(not sent: .*(certif|PKIX)");
                assertThat(names(vsftpd.drop())).isEmpty();
            }
            try (Deliveries d = Deliveries.start(List.of(deployment(dir, vsftpd.url(), "password_file", password.toString(),
                    "trust", vsftpd.certificate().toString())))) {
                arrive(d, DacFixtures.raw(SEG + ".sbd"));
                arrive(d, DacFixtures.raw(SEG + ".tbd"));
                settle(d);
                assertThat(d.status(List.of())).contains("10 profiles (10 sent)");
                List<String> sent = names(vsftpd.drop());
                assertThat(sent).hasSize(10).allMatch(n -> n.endsWith("_rt.nc"));
                for (String n : sent) {
                    assertThat(Files.readAllBytes(vsftpd.drop().resolve(n))).isEqualTo(Files.readAllBytes(dir.resolve("dac/profiles/" + n)));
                }
            }
        }
    }

    @Test
    void aDeploymentWithBadSettingsIsRefusedWithEveryReason(@TempDir Path dir) throws Exception {
        Path meta = dir.resolve("meta.json");
        Files.writeString(meta, Files.readString(DacFixtures.meta()).replace("\"wmo_id\": \"4802989\"", "\"wmo_id\": 4802989"));
        Path f = dir.resolve("d.json");
        Files.writeString(f, "{\"glider\": \"rosie 713\", \"metadata\": \"meta.json\", \"destination\": \"http://example.org/x\","
                + " \"min_samples\": \"many\", \"colour\": \"red\"}");
        assertThatThrownBy(() -> Deliveries.start(List.of(f))).isInstanceOf(DacException.class)
                .hasMessageContaining("problems in the deployment")
                .hasMessageContaining("unknown key 'colour'")
                .hasMessageContaining("glider must be the glider's name")
                .hasMessageContaining("destination must be sftp://USER@HOST[:PORT]/FOLDER or ftps://")
                .hasMessageContaining("min_samples must be a number")
                .hasMessageContaining("wmo_id must be a string, found number 4802989");
        assertThat(names(dir)).containsExactly("d.json", "meta.json");
        Files.writeString(f, "{\"glider\": \"rosie_713\", \"metadata\": \"" + DacFixtures.meta() + "\", \"destination\": \"sftp://u@127.0.0.1/x\"}");
        assertThatThrownBy(() -> Deliveries.start(List.of(f))).isInstanceOf(DacException.class)
                .hasMessageContaining("key is missing: an SFTP destination needs the private key")
                .hasMessageContaining("known_hosts is missing");
    }

    interface Step {
        void run() throws Exception;
    }

    static void call(Step s) {
        try {
            s.run();
        } catch (Exception e) {
            throw new AssertionError(e);
        }
    }
}
