package org.ripv.testing;

import java.io.IOException;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.ripv.probe.FreePorts;

/**
 * Debian's vsftpd on a loopback port for a test, speaking FTPS with explicit TLS only (plain FTP
 * log-ins and data refused), with a configuration and a self-signed certificate of its own
 * ({@code CN=127.0.0.1}, subjectAltName {@code IP:127.0.0.1}). The log-in is vsftpd's anonymous
 * one, kept to a folder of the test's: a password log-in of a local user would need a system user
 * and PAM set up for the test, which a test must not do to the machine. Runs as root only (vsftpd
 * drops to the {@code ftp} user for the session); skipped with the reason otherwise, or when
 * vsftpd is not installed (.ci/run installs it).
 */
public final class LoopbackVsftpd implements AutoCloseable {
    private final Process vsftpd;
    private final int port;
    private final Path drop;
    private final Path cert;

    private LoopbackVsftpd(Process vsftpd, int port, Path drop, Path cert) {
        this.vsftpd = vsftpd;
        this.port = port;
        this.drop = drop;
        this.cert = cert;
    }

    /** Starts the server with its files in {@code dir}; uploads land in {@link #drop()}. */
    public static LoopbackVsftpd start(Path dir) throws IOException, InterruptedException {
        skipUnless(Files.isExecutable(Path.of("/usr/sbin/vsftpd")), "Debian's vsftpd (/usr/sbin/vsftpd) is not installed");
        skipUnless(System.getProperty("user.name").equals("root"), "vsftpd's anonymous log-in needs root to start it");
        Process id = new ProcessBuilder("id", "-u", "ftp").redirectErrorStream(true).start();
        skipUnless(id.waitFor() == 0, "there is no 'ftp' user (vsftpd's package makes it)");
        Path root = Files.createDirectories(dir.resolve("ftp-root"));
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        Files.setPosixFilePermissions(root, PosixFilePermissions.fromString("r-xr-xr-x"));
        Path drop = Files.createDirectories(root.resolve("drop"));
        LoopbackSshd.run(dir, "chown", "ftp:ftp", drop.toString());
        Path empty = Files.createDirectories(dir.resolve("empty"));
        Path cert = dir.resolve("cert.pem");
        Path key = dir.resolve("key.pem");
        LoopbackSshd.run(dir, "openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "2", "-subj", "/CN=127.0.0.1",
                "-addext", "subjectAltName=IP:127.0.0.1", "-keyout", key.toString(), "-out", cert.toString());
        int port = FreePorts.one();
        int pasv = FreePorts.one();
        Path config = dir.resolve("vsftpd.conf");
        Files.writeString(config, String.join("\n",
                "listen=YES", "listen_ipv6=NO", "listen_address=127.0.0.1", "listen_port=" + port, "background=NO",
                "run_as_launching_user=NO", "seccomp_sandbox=NO", "secure_chroot_dir=" + empty,
                "local_enable=NO", "anonymous_enable=YES", "anon_root=" + root, "no_anon_password=NO",
                "write_enable=YES", "anon_upload_enable=YES", "anon_other_write_enable=YES", "anon_umask=022",
                "ssl_enable=YES", "allow_anon_ssl=YES", "force_anon_logins_ssl=YES", "force_anon_data_ssl=YES",
                "ssl_sslv2=NO", "ssl_sslv3=NO", "require_ssl_reuse=NO", "ssl_ciphers=HIGH",
                "rsa_cert_file=" + cert, "rsa_private_key_file=" + key,
                "pasv_enable=YES", "pasv_address=127.0.0.1", "pasv_min_port=" + pasv, "pasv_max_port=" + pasv,
                "xferlog_enable=YES", "vsftpd_log_file=" + dir.resolve("vsftpd.log"), "dual_log_enable=YES",
                "xferlog_file=" + dir.resolve("xfer.log"), ""));
        Process p = new ProcessBuilder("/usr/sbin/vsftpd", config.toString()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("vsftpd.out").toFile()).start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (true) {
            try (Socket s = new Socket("127.0.0.1", port)) {
                break;
            } catch (IOException notYet) {
                if (!p.isAlive() || System.nanoTime() > deadline) {
                    p.destroy();
                    throw new IOException("vsftpd did not listen on " + port + ": " + Files.readString(dir.resolve("vsftpd.out")));
                }
                Thread.sleep(100);
            }
        }
        return new LoopbackVsftpd(p, port, drop, cert);
    }

    private static void skipUnless(boolean ok, String why) {
        if (ok) {
            return;
        }
        if (System.getenv("RIPV_REQUIRE_TOOLS") != null) {
            throw new AssertionError("RIPV_REQUIRE_TOOLS is set but " + why);
        }
        Assumptions.abort(why);
    }

    /** {@code ftps://anonymous@127.0.0.1:PORT/drop} (the folder as the chrooted session sees it). */
    public String url() {
        return "ftps://anonymous@127.0.0.1:" + port + "/drop";
    }

    public int port() {
        return port;
    }

    public Path drop() {
        return drop;
    }

    /** The server's self-signed certificate (PEM): what a client pins. */
    public Path certificate() {
        return cert;
    }

    @Override
    public void close() throws InterruptedException {
        vsftpd.destroy();
        vsftpd.waitFor(10, TimeUnit.SECONDS);
    }
}
