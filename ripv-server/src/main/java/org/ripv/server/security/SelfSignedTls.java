package org.ripv.server.security;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.SecureRandom;
import java.security.cert.Certificate;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import org.ripv.files.PrivateFiles;
import org.ripv.naming.Handles;
import org.ripv.security.Fingerprint;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server's own TLS identity in {@code DATA/tls/}: on the first start the JDK's keytool makes
 * an EC key pair and a self-signed certificate ({@code server.p12}, with a random password in
 * {@code server.pass}), both readable by the owner only; later starts load them. Clients trust
 * it on first use by its SHA-256 fingerprint, which the server prints at every start.
 */
public final class SelfSignedTls {
    private static final Logger log = LoggerFactory.getLogger(SelfSignedTls.class);

    /** A loaded identity: the context to serve with and the certificate's fingerprint. */
    public record Identity(SSLContext context, String fingerprint, Path keystore) {}

    private SelfSignedTls() {}

    /** Loads {@code dir/server.p12}, making it first when there is none. */
    public static Identity loadOrCreate(Path dir) throws IOException {
        Path ks = dir.resolve("server.p12");
        Path pass = dir.resolve("server.pass");
        if (!Files.isRegularFile(ks) || !Files.isRegularFile(pass)) {
            create(dir, ks, pass);
        }
        return load(ks, Files.readString(pass, StandardCharsets.UTF_8).trim().toCharArray());
    }

    /** Loads a PKCS12 key store (an operator's real certificate, or the one made here). */
    public static Identity load(Path keystore, char[] password) throws IOException {
        try (InputStream in = Files.newInputStream(keystore)) {
            KeyStore store = KeyStore.getInstance("PKCS12");
            store.load(in, password);
            Certificate cert = null;
            for (String alias : Collections.list(store.aliases())) {
                if (store.isKeyEntry(alias)) {
                    cert = store.getCertificate(alias);
                    break;
                }
            }
            if (cert == null) {
                throw new IOException(keystore + " holds no private key with a certificate");
            }
            KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
            kmf.init(store, password);
            SSLContext ctx = SSLContext.getInstance("TLS");
            ctx.init(kmf.getKeyManagers(), null, null);
            return new Identity(ctx, Fingerprint.of(cert), keystore);
        } catch (GeneralSecurityException e) {
            throw new IOException("cannot use the key store " + keystore + ": " + e.getMessage(), e);
        }
    }

    private static void create(Path dir, Path ks, Path pass) throws IOException {
        ownerOnlyDirectory(dir);
        byte[] r = new byte[18];
        new SecureRandom().nextBytes(r);
        String password = HexFormat.of().formatHex(r);
        Path tmp = dir.resolve("server.p12.tmp");
        Files.deleteIfExists(tmp);
        String keytool = Path.of(System.getProperty("java.home"), "bin", "keytool").toString();
        List<String> cmd = new ArrayList<>(List.of(keytool, "-genkeypair", "-alias", "ripv", "-keyalg", "EC",
                "-groupname", "secp256r1", "-sigalg", "SHA256withECDSA", "-validity", "3650",
                "-dname", "CN=" + commonName(), "-ext", "SAN=" + subjectAltNames(), "-storetype", "PKCS12",
                "-keystore", tmp.toString(), "-storepass:env", "RIPV_KS_PASS"));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().put("RIPV_KS_PASS", password);
        try {
            Process p = pb.start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            if (!p.waitFor(120, TimeUnit.SECONDS) || p.exitValue() != 0) {
                p.destroyForcibly();
                throw new IOException("keytool could not make the server's key pair: " + out.trim());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while making the server's key pair", e);
        }
        ownerOnly(tmp);
        writeOwnerOnly(pass, password + "\n");
        Files.move(tmp, ks, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        log.info("made a new TLS key pair and self-signed certificate in {}", ks);
    }

    private static String commonName() {
        String h = Handles.localHost();
        return h.matches("[A-Za-z0-9.\\-]{1,200}") ? h : "ripv";
    }

    private static String subjectAltNames() {
        String h = commonName();
        return "dns:localhost,ip:127.0.0.1,ip:::1" + (h.equals("localhost") || h.equals("ripv") ? "" : ",dns:" + h);
    }

    static void ownerOnlyDirectory(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            try {
                Files.createDirectories(dir, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
            } catch (UnsupportedOperationException e) {
                Files.createDirectories(dir);
            }
        }
        try {
            Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwx------"));
        } catch (UnsupportedOperationException ignored) {
            // not a POSIX file system
        }
    }

    private static void ownerOnly(Path f) throws IOException {
        try {
            Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-------"));
        } catch (UnsupportedOperationException ignored) {
            // not a POSIX file system
        }
    }

    private static void writeOwnerOnly(Path f, String text) throws IOException {
        PrivateFiles.replace(f, text);
    }
}
