package org.ripv.dac;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.ingest.SensorListCache;

/**
 * {@link SftpPush} against Debian's OpenSSH server, started by the test on a loopback port with a
 * configuration of its own (key authentication only, internal-sftp): rosie_713's ten profiles
 * pushed, in the server's folder byte for byte, in the ledger; pushed again: nothing sent; an
 * unknown host key: refused, nothing sent; a file that fails the DAC check: kept, not sent.
 */
class SftpPushTest {
    Process sshd;

    @AfterEach
    void stop() throws InterruptedException {
        if (sshd != null) {
            sshd.destroy();
            sshd.waitFor(10, TimeUnit.SECONDS);
        }
    }

    record Server(int port, Path dropDir, Path key, Path knownHosts, String user) {
    }

    Server start(Path dir) throws Exception {
        assumeTrue(Files.isExecutable(Path.of("/usr/sbin/sshd")), "Debian's openssh-server is not installed");
        String user = System.getProperty("user.name");
        if (user.equals("root")) {
            Files.createDirectories(Path.of("/run/sshd")); // sshd's privilege-separation folder, which a fresh container lacks
        }
        DacFixtures.run(dir, "ssh-keygen", "-q", "-t", "ecdsa", "-N", "", "-f", dir.resolve("host_key").toString());
        DacFixtures.run(dir, "ssh-keygen", "-q", "-t", "ecdsa", "-N", "", "-f", dir.resolve("client_key").toString());
        Files.copy(dir.resolve("client_key.pub"), dir.resolve("authorized_keys"));
        int port;
        try (ServerSocket s = new ServerSocket(0)) {
            port = s.getLocalPort();
        }
        Path drop = Files.createDirectories(dir.resolve("drop"));
        Path config = dir.resolve("sshd_config");
        Files.writeString(config, String.join("\n",
                "Port " + port, "ListenAddress 127.0.0.1", "HostKey " + dir.resolve("host_key"),
                "AuthorizedKeysFile " + dir.resolve("authorized_keys"), "PasswordAuthentication no",
                "KbdInteractiveAuthentication no", "PubkeyAuthentication yes", "UsePAM no", "StrictModes no",
                "PermitRootLogin prohibit-password", "PidFile " + dir.resolve("sshd.pid"), "Subsystem sftp internal-sftp", ""));
        sshd = new ProcessBuilder("/usr/sbin/sshd", "-D", "-e", "-f", config.toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("sshd.log").toFile()).start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (true) {
            try (Socket s = new Socket("127.0.0.1", port)) {
                break;
            } catch (IOException notYet) {
                assertThat(sshd.isAlive()).as(Files.readString(dir.resolve("sshd.log"))).isTrue();
                assertThat(System.nanoTime()).as("sshd listening").isLessThan(deadline);
                Thread.sleep(100);
            }
        }
        String hostKey = Files.readString(dir.resolve("host_key.pub")).trim();
        Path known = dir.resolve("known_hosts");
        Files.writeString(known, "[127.0.0.1]:" + port + " " + hostKey.substring(0, hostKey.lastIndexOf(' ')) + "\n");
        return new Server(port, drop, dir.resolve("client_key"), known, user);
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
