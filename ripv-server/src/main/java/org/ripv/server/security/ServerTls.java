package org.ripv.server.security;

import java.io.IOException;
import java.nio.file.Path;
import javax.net.ServerSocketFactory;
import javax.net.ssl.SSLContext;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What the client port and the landing page serve with: the operator's TLS context
 * ({@code --tls-keystore}), the server's own self-signed identity (made on first start), or
 * nothing with {@code --plain}.
 *
 * @param context     the TLS context, or null for plain TCP
 * @param fingerprint the server's own certificate's fingerprint, or null (plain, or the operator's key store)
 */
public record ServerTls(SSLContext context, String fingerprint) {
    private static final Logger log = LoggerFactory.getLogger(ServerTls.class);

    /** Decides, loading or making the server's own identity in {@code dir} when needed. */
    public static ServerTls resolve(SSLContext given, boolean plain, Path dir) throws IOException {
        if (given != null) {
            return new ServerTls(given, null);
        }
        if (plain) {
            return new ServerTls(null, null);
        }
        SelfSignedTls.Identity id = SelfSignedTls.loadOrCreate(dir);
        log.info("TLS certificate fingerprint {} (clients see it on first connecting)", id.fingerprint());
        return new ServerTls(id.context(), id.fingerprint());
    }

    public ServerSocketFactory serverSockets() {
        return context == null ? ServerSocketFactory.getDefault() : context.getServerSocketFactory();
    }

    /** " (TLS)" or " (plain TCP)", for log lines and the landing page. */
    public String label() {
        return context == null ? " (plain TCP)" : " (TLS)";
    }
}
