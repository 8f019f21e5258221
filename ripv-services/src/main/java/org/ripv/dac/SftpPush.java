package org.ripv.dac;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyPair;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.apache.sshd.client.SshClient;
import org.apache.sshd.client.keyverifier.KnownHostsServerKeyVerifier;
import org.apache.sshd.client.keyverifier.RejectAllServerKeyVerifier;
import org.apache.sshd.client.session.ClientSession;
import org.apache.sshd.common.util.security.SecurityUtils;
import org.apache.sshd.sftp.client.SftpClient;
import org.apache.sshd.sftp.client.SftpClientFactory;

/**
 * Pushes profile files to the DAC's SFTP drop (the deployment's folder) with Apache MINA SSHD's
 * client: key authentication only, the server's host key checked against a known-hosts file
 * (an unknown or changed key is refused, never added), each file uploaded as {@code NAME.part}
 * and renamed when whole. A file is checked ({@link ProfileChecker}) before it is sent; one that
 * fails is reported and kept, not sent. Every outcome goes into the {@link DacLedger}; a file
 * already sent (same name, same bytes) is not sent again; a failed connection is retried with
 * back-off (1 s, 2 s, 4 s …).
 */
public final class SftpPush implements ProfilePush {
    /** One file's outcome. */
    public record Outcome(Path file, String status, String detail) {
    }

    private final URI destination;
    private final Path key;
    private final Path knownHosts;
    private final DacLedger ledger;
    private final int attempts;
    private final Duration firstBackoff;

    /** {@code sftp://USER@HOST[:PORT]/FOLDER}. */
    public SftpPush(URI destination, Path key, Path knownHosts, DacLedger ledger, int attempts, Duration firstBackoff) throws DacException {
        if (!"sftp".equals(destination.getScheme()) || destination.getHost() == null || destination.getUserInfo() == null) {
            throw new DacException("the destination must be sftp://USER@HOST[:PORT]/FOLDER, not " + destination);
        }
        if (!Files.isReadable(key)) {
            throw new DacException("no private key at " + key);
        }
        if (!Files.isReadable(knownHosts)) {
            throw new DacException("no known-hosts file at " + knownHosts + ": the server's host key must be known before a push");
        }
        this.destination = destination;
        this.key = key;
        this.knownHosts = knownHosts;
        this.ledger = ledger;
        this.attempts = Math.max(1, attempts);
        this.firstBackoff = firstBackoff;
    }

    @Override
    public List<Outcome> push(List<Path> files) throws IOException, InterruptedException {
        String dest = destination.toString();
        List<Outcome> out = new ArrayList<>();
        List<Path> toSend = new ArrayList<>();
        ProfileChecker checker = new ProfileChecker();
        for (Path f : files) {
            String sha = DacLedger.sha256(f);
            if (ledger.wasSent(dest, f, sha)) {
                out.add(new Outcome(f, "already sent", "the ledger has it"));
                continue;
            }
            ProfileChecker.Report r = checker.check(f);
            if (!r.passed()) {
                String why = "fails the DAC check, kept, not sent: " + String.join("; ", r.failures());
                ledger.record(dest, f, sha, false, why);
                out.add(new Outcome(f, "not sent", why));
                continue;
            }
            toSend.add(f);
        }
        if (toSend.isEmpty()) {
            return out;
        }
        Duration wait = firstBackoff;
        for (int attempt = 1; ; attempt++) {
            try {
                send(toSend, out);
                return out;
            } catch (IOException e) {
                if (attempt >= attempts) {
                    String why = "not sent after " + attempt + " attempt" + (attempt == 1 ? "" : "s") + ": " + e.getMessage();
                    for (Path f : toSend) {
                        if (out.stream().noneMatch(o -> o.file().equals(f))) {
                            ledger.record(dest, f, DacLedger.sha256(f), false, why);
                            out.add(new Outcome(f, "failed", why));
                        }
                    }
                    return out;
                }
                Thread.sleep(wait.toMillis());
                wait = wait.multipliedBy(2);
            }
        }
    }

    private void send(List<Path> files, List<Outcome> out) throws IOException {
        SshClient client = SshClient.setUpDefaultClient();
        client.setServerKeyVerifier(new KnownHostsServerKeyVerifier(RejectAllServerKeyVerifier.INSTANCE, knownHosts));
        client.start();
        try {
            int port = destination.getPort() < 0 ? 22 : destination.getPort();
            try (ClientSession session = client.connect(destination.getUserInfo(), destination.getHost(), port)
                    .verify(Duration.ofSeconds(20)).getSession()) {
                Iterable<KeyPair> keys;
                try (InputStream in = Files.newInputStream(key)) {
                    keys = SecurityUtils.loadKeyPairIdentities(session, null, in, null);
                } catch (GeneralSecurityException e) {
                    throw new IOException("cannot read the private key " + key + ": " + e.getMessage(), e);
                }
                for (KeyPair k : keys) {
                    session.addPublicKeyIdentity(k);
                }
                session.auth().verify(Duration.ofSeconds(20));
                String folder = destination.getPath() == null || destination.getPath().isEmpty() ? "." : destination.getPath();
                try (SftpClient sftp = SftpClientFactory.instance().createSftpClient(session)) {
                    for (Path f : files) {
                        if (out.stream().anyMatch(o -> o.file().equals(f))) {
                            continue; // sent in an earlier attempt of this push
                        }
                        String name = f.getFileName().toString();
                        String part = folder + "/" + name + ".part";
                        try (OutputStream os = sftp.write(part)) {
                            Files.copy(f, os);
                        }
                        try {
                            sftp.remove(folder + "/" + name);
                        } catch (IOException absent) {
                            // nothing there yet: the usual case
                        }
                        sftp.rename(part, folder + "/" + name);
                        ledger.record(destination.toString(), f, DacLedger.sha256(f), true, "sent to " + destination);
                        out.add(new Outcome(f, "sent", "to " + destination));
                    }
                }
            }
        } finally {
            client.stop();
        }
    }
}
