package org.ripv.testing;

import java.io.IOException;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.ripv.probe.FreePorts;

/**
 * Debian's OpenSSH server on a loopback port for a test, with a configuration of its own: a new
 * host key, key authentication only (a new client key), internal-sftp, a drop folder. The test
 * gets the port, the client key and a known_hosts file holding the host key. Skipped with the
 * reason when openssh-server is not installed (.ci/run installs it).
 */
public final class LoopbackSshd implements AutoCloseable {
    private Process sshd;
    private final Path dir;
    private final int port;
    private final Path drop;
    private final Path key;
    private final Path knownHosts;
    private final String user;

    private LoopbackSshd(Path dir, Process sshd, int port, Path drop, Path key, Path knownHosts, String user) {
        this.dir = dir;
        this.sshd = sshd;
        this.port = port;
        this.drop = drop;
        this.key = key;
        this.knownHosts = knownHosts;
        this.user = user;
    }

    /** Starts the server with its files in {@code dir}. */
    public static LoopbackSshd start(Path dir) throws IOException, InterruptedException {
        if (!Files.isExecutable(Path.of("/usr/sbin/sshd"))) {
            if (System.getenv("RIPV_REQUIRE_TOOLS") != null) {
                throw new AssertionError("RIPV_REQUIRE_TOOLS is set but Debian's openssh-server is not installed");
            }
            Assumptions.abort("Debian's openssh-server (/usr/sbin/sshd) is not installed");
        }
        String user = System.getProperty("user.name");
        if (user.equals("root")) {
            Files.createDirectories(Path.of("/run/sshd")); // sshd's privilege-separation folder, which a fresh container lacks
        }
        run(dir, "ssh-keygen", "-q", "-t", "ecdsa", "-N", "", "-f", dir.resolve("host_key").toString());
        run(dir, "ssh-keygen", "-q", "-t", "ecdsa", "-N", "", "-f", dir.resolve("client_key").toString());
        Files.copy(dir.resolve("client_key.pub"), dir.resolve("authorized_keys"));
        int port = FreePorts.one();
        Path drop = Files.createDirectories(dir.resolve("drop"));
        Path config = dir.resolve("sshd_config");
        Files.writeString(config, String.join("\n",
                "Port " + port, "ListenAddress 127.0.0.1", "HostKey " + dir.resolve("host_key"),
                "AuthorizedKeysFile " + dir.resolve("authorized_keys"), "PasswordAuthentication no",
                "KbdInteractiveAuthentication no", "PubkeyAuthentication yes", "UsePAM no", "StrictModes no",
                "PermitRootLogin prohibit-password", "PidFile " + dir.resolve("sshd.pid"), "Subsystem sftp internal-sftp", ""));
        Process sshd = launch(dir, port);
        String hostKey = Files.readString(dir.resolve("host_key.pub")).trim();
        Path known = dir.resolve("known_hosts");
        Files.writeString(known, "[127.0.0.1]:" + port + " " + hostKey.substring(0, hostKey.lastIndexOf(' ')) + "\n");
        return new LoopbackSshd(dir, sshd, port, drop, dir.resolve("client_key"), known, user);
    }

    private static Process launch(Path dir, int port) throws IOException, InterruptedException {
        Process sshd = new ProcessBuilder("/usr/sbin/sshd", "-D", "-e", "-f", dir.resolve("sshd_config").toString())
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.appendTo(dir.resolve("sshd.log").toFile())).start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (true) {
            try (Socket s = new Socket("127.0.0.1", port)) {
                return sshd;
            } catch (IOException notYet) {
                if (!sshd.isAlive() || System.nanoTime() > deadline) {
                    sshd.destroy();
                    throw new IOException("sshd did not listen on " + port + ": " + Files.readString(dir.resolve("sshd.log")));
                }
                Thread.sleep(100);
            }
        }
    }

    /** Stops the server (a push to it fails) until {@link #resume}. */
    public void stop() throws InterruptedException {
        sshd.destroy();
        sshd.waitFor(10, TimeUnit.SECONDS);
    }

    /** Starts it again on the same port with the same keys. */
    public void resume() throws IOException, InterruptedException {
        sshd = launch(dir, port);
    }

    /** {@code sftp://USER@127.0.0.1:PORT/DROP}. */
    public String url() {
        return "sftp://" + user + "@127.0.0.1:" + port + drop.toAbsolutePath();
    }

    public int port() {
        return port;
    }

    public Path drop() {
        return drop;
    }

    public Path key() {
        return key;
    }

    public Path knownHosts() {
        return knownHosts;
    }

    static void run(Path dir, String... cmd) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes());
        if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
            throw new IOException(String.join(" ", cmd) + " failed: " + out);
        }
    }

    @Override
    public void close() throws InterruptedException {
        stop();
    }
}
