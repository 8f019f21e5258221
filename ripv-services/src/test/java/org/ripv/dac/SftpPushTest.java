package org.ripv.dac;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.ingest.SensorListCache;
import org.ripv.testing.LoopbackSshd;

/**
 * {@link SftpPush} against Debian's OpenSSH server, started by the test on a loopback port with a
 * configuration of its own (key authentication only, internal-sftp): rosie_713's ten profiles
 * pushed, in the server's folder byte for byte, in the ledger; pushed again: nothing sent; an
 * unknown host key: refused, nothing sent; a file that fails the DAC check: kept, not sent.
 */
class SftpPushTest {
    LoopbackSshd sshd;

    @AfterEach
    void stop() throws InterruptedException {
        if (sshd != null) {
            sshd.close();
        }
    }

    record Server(int port, Path dropDir, Path key, Path knownHosts, String user) {
    }

    Server start(Path dir) throws Exception {
        sshd = LoopbackSshd.start(dir);
        return new Server(sshd.port(), sshd.drop(), sshd.key(), sshd.knownHosts(), System.getProperty("user.name"));
    }

    List<Path> profiles(Path out) throws Exception {
        String seg = "rosie_713-2019-166-0-157";
        return new DacRun(new SegmentReader(new SensorListCache(DacFixtures.cache())), ProfileSplitter.defaults(),
                new ProfileWriter(Metadata.read(DacFixtures.meta()), QcConfig.read(DacFixtures.qc())), new ProfileChecker())
                .run(List.of(DacFixtures.raw(seg + ".sbd"), DacFixtures.raw(seg + ".tbd")), out).written();
    }

    @Test
    void profilesArePushedOnceWithKeysAndAKnownHost(@TempDir Path dir, @TempDir Path out) throws Exception {
        Server s = start(dir);
        List<Path> files = profiles(out);
        URI to = URI.create("sftp://" + s.user() + "@127.0.0.1:" + s.port() + s.dropDir());
        DacLedger ledger = new DacLedger(out.resolve("dac-ledger.tsv"));
        List<SftpPush.Outcome> r = new SftpPush(to, s.key(), s.knownHosts(), ledger, 2, Duration.ofMillis(100)).push(files);
        assertThat(r).extracting(SftpPush.Outcome::status).containsOnly("sent").hasSize(10);
        for (Path f : files) {
            assertThat(s.dropDir().resolve(f.getFileName())).hasSameBinaryContentAs(f);
        }
        assertThat(s.dropDir().toFile().list((d, n) -> n.endsWith(".part"))).isEmpty();
        assertThat(ledger.lines()).hasSize(10).allMatch(l -> l.contains("\tsent\t"));

        // again, with a fresh ledger object read from its file: nothing is sent twice
        List<SftpPush.Outcome> again = new SftpPush(to, s.key(), s.knownHosts(), new DacLedger(out.resolve("dac-ledger.tsv")), 2,
                Duration.ofMillis(100)).push(files);
        assertThat(again).extracting(SftpPush.Outcome::status).containsOnly("already sent");
        assertThat(ledger.lines()).hasSize(10);
    }

    @Test
    void anUnknownHostKeyIsRefusedAndAFailingFileIsKept(@TempDir Path dir, @TempDir Path out) throws Exception {
        Server s = start(dir);
        List<Path> files = profiles(out);
        Path other = dir.resolve("other_key");
        DacFixtures.run(dir, "ssh-keygen", "-q", "-t", "ecdsa", "-N", "", "-f", other.toString());
        Path wrongKnown = dir.resolve("known_hosts_wrong");
        String k = Files.readString(dir.resolve("other_key.pub")).trim();
        Files.writeString(wrongKnown, "[127.0.0.1]:" + s.port() + " " + k.substring(0, k.lastIndexOf(' ')) + "\n");
        URI to = URI.create("sftp://" + s.user() + "@127.0.0.1:" + s.port() + s.dropDir());
        DacLedger ledger = new DacLedger(out.resolve("dac-ledger.tsv"));
        List<SftpPush.Outcome> r = new SftpPush(to, s.key(), wrongKnown, ledger, 2, Duration.ofMillis(100)).push(files.subList(0, 2));
        assertThat(r).extracting(SftpPush.Outcome::status).containsOnly("failed");
        assertThat(r.get(0).detail()).contains("not sent after 2 attempts");
        assertThat(s.dropDir().toFile().list()).isEmpty();

        Path broken = out.resolve("broken_20190620T000000Z_rt.nc");
        DacFixtures.run(out, "ncgen", "-o", broken.toString(), DacFixtures.shared().resolve("../dac/IOOS_Glider_NetCDF_v2.0.cdl").normalize().toString());
        List<SftpPush.Outcome> b = new SftpPush(to, s.key(), s.knownHosts(), ledger, 1, Duration.ofMillis(100)).push(List.of(broken, files.get(2)));
        assertThat(b).extracting(SftpPush.Outcome::status).containsExactly("not sent", "sent");
        assertThat(b.get(0).detail()).contains("fails the DAC check");
        assertThat(s.dropDir().toFile().list()).containsExactly(files.get(2).getFileName().toString());
        assertThat(broken).exists();
    }
}
