package org.ripv.client.handlers;

import java.io.IOException;
import java.nio.file.Path;
import javax.net.SocketFactory;
import picocli.CommandLine.Option;

/**
 * {@code --truststore} and {@code --truststore-password} (a picocli mixin of {@code ripv cli}): a key
 * store holding a CA-signed or exported certificate to check the server against, instead of
 * trusting it on first use as {@link ServerTrustOptions} does by default.
 */
public final class TrustStoreOptions {
    @Option(names = "--truststore", description = "Check the server's certificate against this key store (a CA-signed or"
            + " exported certificate) instead of trusting it on first use.")
    Path truststore;

    @Option(names = "--truststore-password", defaultValue = "changeit", description = "The trust store's password (default ${DEFAULT-VALUE}).")
    String truststorePassword;

    /** Whether a trust store was given. */
    public boolean given() {
        return truststore != null;
    }

    /** Sockets that trust the store's certificates, or null without {@code --truststore}. */
    public SocketFactory socketFactory() throws IOException {
        return truststore == null ? null : Tls.socketFactory(truststore, truststorePassword.toCharArray());
    }
}
