package org.ripv.server.security;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code ripv server}'s TLS options (a picocli mixin): the server's own certificate by default,
 * a real one from {@code --tls-keystore}, or none with {@code --plain}. The rules between the
 * three live here with them.
 */
public final class TlsOptions {
    @Option(names = "--tls-keystore", description = "A PKCS12 key store with a real certificate (default: the server's own,"
            + " made on first start in DATA/tls/).")
    Path tlsKeystore;

    @Option(names = "--tls-password-file", description = "File holding the key store's password.")
    Path tlsPasswordFile;

    @Option(names = "--plain", description = "No TLS on the client port and the landing page (a test lab only: passwords cross in clear).")
    boolean plain;

    /** Whether the server speaks plain TCP and HTTP. */
    public boolean plain() {
        return plain;
    }

    /** Refuses {@code --plain} with {@code --tls-keystore}, and a key store without its password file. */
    public void check() {
        if (tlsKeystore != null && plain) {
            throw new IllegalArgumentException("--plain and --tls-keystore exclude each other");
        }
        if (tlsKeystore != null && tlsPasswordFile == null) {
            throw new IllegalArgumentException("--tls-keystore needs --tls-password-file");
        }
    }

    /** The identity {@code --tls-keystore} names, or null for the server's own certificate. */
    public SelfSignedTls.Identity identity() throws Exception {
        return tlsKeystore == null ? null : identity(tlsKeystore, tlsPasswordFile);
    }

    /** A TLS identity from a PKCS12 key store and a file holding its password (its first line). */
    public static SelfSignedTls.Identity identity(Path keystore, Path passwordFile) throws Exception {
        if (passwordFile == null) {
            throw new IllegalArgumentException("--tls-keystore needs --tls-password-file");
        }
        char[] pw = Files.readString(passwordFile, StandardCharsets.UTF_8).trim().toCharArray();
        return SelfSignedTls.load(keystore, pw);
    }
}
