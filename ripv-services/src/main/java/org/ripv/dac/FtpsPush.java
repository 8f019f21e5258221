package org.ripv.dac;

import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.cert.Certificate;
import java.security.cert.CertificateFactory;
import java.util.ArrayList;
import java.util.List;
import javax.net.ssl.TrustManagerFactory;
import javax.net.ssl.X509TrustManager;
import org.apache.commons.net.ftp.FTP;
import org.apache.commons.net.ftp.FTPReply;
import org.apache.commons.net.ftp.FTPSClient;

/**
 * Pushes profile files to a DAC drop over FTPS with commons-net's {@link FTPSClient}: explicit
 * TLS ({@code AUTH TLS} on the control connection, {@code PROT P} for the data), the server's
 * certificate checked against the deployment's own trust (a pinned certificate in PEM, or a
 * PKCS#12/JKS trust store) and its host name against the certificate, never the JVM's default
 * authorities and never "trust all". Otherwise as {@link SftpPush}: each file checked first, sent
 * as {@code NAME.part} and renamed, every outcome in the ledger, nothing sent twice. One
 * connection attempt a call: the caller retries.
 */
public final class FtpsPush implements ProfilePush {
    private final URI destination;
    private final String password;
    private final X509TrustManager trust;
    private final DacLedger ledger;

    /** {@code ftps://USER@HOST[:PORT]/FOLDER}; the password is the first line of {@code passwordFile}. */
    public FtpsPush(URI destination, Path passwordFile, Path trustFile, DacLedger ledger) throws DacException {
        if (!"ftps".equals(destination.getScheme()) || destination.getHost() == null || destination.getUserInfo() == null) {
            throw new DacException("the destination must be ftps://USER@HOST[:PORT]/FOLDER, not " + destination);
        }
        try {
            List<String> lines = Files.readAllLines(passwordFile, StandardCharsets.UTF_8);
            if (lines.isEmpty() || lines.get(0).isEmpty()) {
                throw new DacException(passwordFile + " holds no password on its first line");
            }
            this.password = lines.get(0);
        } catch (IOException e) {
            throw new DacException("cannot read the FTPS password file " + passwordFile + ": " + e.getMessage());
        }
        this.trust = trustManager(trustFile);
        this.destination = destination;
        this.ledger = ledger;
    }

    /** The trust of a PEM certificate (or several), or of a PKCS#12/JKS store without a password. */
    static X509TrustManager trustManager(Path file) throws DacException {
        try {
            KeyStore ks;
            byte[] bytes = Files.readAllBytes(file);
            if (new String(bytes, StandardCharsets.ISO_8859_1).contains("-----BEGIN CERTIFICATE-----")) {
                ks = KeyStore.getInstance(KeyStore.getDefaultType());
                ks.load(null, null);
                int i = 0;
                try (InputStream in = Files.newInputStream(file)) {
                    for (Certificate c : CertificateFactory.getInstance("X.509").generateCertificates(in)) {
                        ks.setCertificateEntry("pinned-" + i++, c);
                    }
                }
                if (i == 0) {
                    throw new DacException(file + " holds no certificate");
                }
            } else {
                ks = KeyStore.getInstance(file.toFile(), (char[]) null);
            }
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(ks);
            for (var tm : tmf.getTrustManagers()) {
                if (tm instanceof X509TrustManager x) {
                    return x;
                }
            }
            throw new DacException(file + ": no X.509 trust manager for it");
        } catch (IOException | GeneralSecurityException e) {
            throw new DacException("cannot read the FTPS trust " + file + " (a PEM certificate or a PKCS#12/JKS trust store): "
                    + e.getMessage());
        }
    }

    @Override
    public List<SftpPush.Outcome> push(List<Path> files) throws IOException {
        String dest = destination.toString();
        List<SftpPush.Outcome> out = new ArrayList<>();
        List<Path> toSend = new ArrayList<>();
        ProfileChecker checker = new ProfileChecker();
        for (Path f : files) {
            String sha = DacLedger.sha256(f);
            if (ledger.wasSent(dest, f, sha)) {
                out.add(new SftpPush.Outcome(f, "already sent", "the ledger has it"));
                continue;
            }
            ProfileChecker.Report r = checker.check(f);
            if (!r.passed()) {
                String why = "fails the DAC check, kept, not sent: " + String.join("; ", r.failures());
                ledger.record(dest, f, sha, false, why);
                out.add(new SftpPush.Outcome(f, "not sent", why));
                continue;
            }
            toSend.add(f);
        }
        if (toSend.isEmpty()) {
            return out;
        }
        try {
            send(toSend, out);
        } catch (IOException e) {
            String why = "not sent: " + e.getMessage();
            for (Path f : toSend) {
                if (out.stream().noneMatch(o -> o.file().equals(f))) {
                    ledger.record(dest, f, DacLedger.sha256(f), false, why);
                    out.add(new SftpPush.Outcome(f, "failed", why));
                }
            }
        }
        return out;
    }

    private void send(List<Path> files, List<SftpPush.Outcome> out) throws IOException {
        FTPSClient ftp = new FTPSClient("TLS", false);
        ftp.setTrustManager(trust);
        ftp.setEndpointCheckingEnabled(true);
        ftp.setConnectTimeout(20_000);
        ftp.setDefaultTimeout(20_000);
        try {
            ftp.connect(destination.getHost(), destination.getPort() < 0 ? 21 : destination.getPort());
            expect(ftp, FTPReply.isPositiveCompletion(ftp.getReplyCode()), "the server refused the connection");
            ftp.setSoTimeout(20_000);
            expect(ftp, ftp.login(destination.getUserInfo(), password), "the log-in of " + destination.getUserInfo() + " was refused");
            ftp.execPBSZ(0);
            ftp.execPROT("P");
            expect(ftp, ftp.setFileType(FTP.BINARY_FILE_TYPE), "binary mode was refused");
            ftp.enterLocalPassiveMode();
            String folder = destination.getPath() == null || destination.getPath().isEmpty() ? "" : destination.getPath();
            if (!folder.isEmpty()) {
                expect(ftp, ftp.changeWorkingDirectory(folder), "no folder " + folder + " on the server");
            }
            for (Path f : files) {
                String name = f.getFileName().toString();
                try (InputStream in = Files.newInputStream(f)) {
                    expect(ftp, ftp.storeFile(name + ".part", in), "the upload of " + name + " was refused");
                }
                ftp.deleteFile(name); // nothing there yet: the usual case
                expect(ftp, ftp.rename(name + ".part", name), "the rename of " + name + ".part was refused");
                ledger.record(destination.toString(), f, DacLedger.sha256(f), true, "sent to " + destination);
                out.add(new SftpPush.Outcome(f, "sent", "to " + destination));
            }
            ftp.logout();
        } finally {
            if (ftp.isConnected()) {
                try {
                    ftp.disconnect();
                } catch (IOException ignored) {
                    // the files are recorded; a failed close changes nothing
                }
            }
        }
    }

    private static void expect(FTPSClient ftp, boolean ok, String what) throws IOException {
        if (!ok) {
            throw new IOException(what + " (" + ftp.getReplyString().strip() + ")");
        }
    }
}
