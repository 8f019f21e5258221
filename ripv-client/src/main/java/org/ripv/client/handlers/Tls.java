package org.ripv.client.handlers;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import javax.net.SocketFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocketFactory;
import javax.net.ssl.TrustManagerFactory;

/** Socket factories for connecting to a server that serves its client port over TLS. */
public final class Tls {
    private Tls() {}

    /**
     * A TLS factory that trusts the certificates in {@code truststore} (PKCS12 or JKS), or the
     * JVM's default trust store when it is null.
     */
    public static SocketFactory socketFactory(Path truststore, char[] password) throws IOException {
        if (truststore == null) {
            return SSLSocketFactory.getDefault();
        }
        try (InputStream in = Files.newInputStream(truststore)) {
            KeyStore ks = KeyStore.getInstance(KeyStore.getDefaultType());
            ks.load(in, password);
            TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
            tmf.init(ks);
            SSLContext ctx = SSLContext.getInstance("TLS");
            ctx.init(null, tmf.getTrustManagers(), null);
            return ctx.getSocketFactory();
        } catch (GeneralSecurityException e) {
            throw new IOException("cannot use the trust store " + truststore + ": " + e.getMessage(), e);
        }
    }
}
