package org.ripv.client.handlers;

import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.cert.CertificateException;
import java.security.cert.X509Certificate;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.function.Consumer;
import javax.net.SocketFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLEngine;
import javax.net.ssl.SSLSocketFactory;
import javax.net.ssl.TrustManager;
import javax.net.ssl.TrustManagerFactory;
import javax.net.ssl.X509ExtendedTrustManager;
import org.ripv.failover.ServerList;
import org.ripv.security.Fingerprint;

/**
 * Socket factories for the server's TLS client port. By default a client trusts a server's
 * certificate on first use, as ssh does: the first connection to {@code HOST:PORT} remembers the
 * certificate's SHA-256 fingerprint in {@code ~/.ripv/known_hosts} (or {@code $RIPV_KNOWN_HOSTS},
 * or the system property {@code ripv.knownHosts}); later connections must present the same
 * certificate or are refused with {@link ChangedCertificateException}. With a trust store the
 * usual certificate-authority checks (and host-name checks) apply instead.
 */
public final class Tls {
    /** The system property naming the known-hosts file (tests point it at a temporary file). */
    public static final String KNOWN_HOSTS_PROPERTY = "ripv.knownHosts";

    private Tls() {}

    /** A certificate differs from the one remembered for this host and port. */
    public static final class ChangedCertificateException extends CertificateException {
        private static final long serialVersionUID = 1L;

        ChangedCertificateException(String message) {
            super(message);
        }
    }

    /**
     * A standby's certificate is not known while another server of its list is pinned: trusting
     * it on first use would hand the password to whoever answers there (issue 23, item 2).
     */
    public static final class UnpinnedStandbyException extends CertificateException {
        private static final long serialVersionUID = 1L;

        UnpinnedStandbyException(String message) {
            super(message);
        }
    }

    /**
     * A server's certificate was refused because it differs from the one remembered: the
     * man-in-the-middle signal. A connection to a list of servers stops at the first of these
     * rather than trying the next server (as ssh does), so the password goes to none of them.
     */
    public static final class RefusedCertificate extends IOException {
        private static final long serialVersionUID = 1L;

        RefusedCertificate(String message, Throwable cause) {
            super(message, cause);
        }
    }

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

    /** The known-hosts file: the system property, else $RIPV_KNOWN_HOSTS, else ~/.ripv/known_hosts. */
    public static Path defaultKnownHosts() {
        String p = System.getProperty(KNOWN_HOSTS_PROPERTY);
        if (p == null || p.isBlank()) {
            p = System.getenv("RIPV_KNOWN_HOSTS");
        }
        if (p != null && !p.isBlank()) {
            return Path.of(p);
        }
        return Path.of(System.getProperty("user.home"), ".ripv", "known_hosts");
    }

    /**
     * A TLS factory for {@code host:port} that trusts on first use.
     *
     * @param notices told, once, when a new server's fingerprint is remembered
     */
    public static SocketFactory trustOnFirstUse(String host, int port, Path knownHosts, Consumer<String> notices) throws IOException {
        return trustOnFirstUse(host, port, knownHosts, notices, null);
    }

    /**
     * As {@link #trustOnFirstUse(String, int, Path, Consumer)} for one server of a list ({@code
     * --server A,B}): while another server of the list is pinned, this one is trusted only with a
     * certificate already trusted for one of them (the same {@code --tls-keystore}: learned from a
     * server already trusted) or with its own line in the known-hosts file (pinned by the
     * operator) — never on first use.
     *
     * @param servers the whole list, or null for a single server
     */
    public static SocketFactory trustOnFirstUse(String host, int port, Path knownHosts, Consumer<String> notices,
                                                ServerList servers) throws IOException {
        List<String> group = new ArrayList<>();
        String self = key(host, port);
        if (servers != null) {
            for (int i = 0; i < servers.size(); i++) {
                String k = key(servers.get(i).host(), servers.get(i).port());
                if (!k.equals(self)) {
                    group.add(k);
                }
            }
        }
        try {
            SSLContext ctx = SSLContext.getInstance("TLS");
            ctx.init(null, new TrustManager[] {new FirstUse(self, knownHosts, notices, group)}, null);
            return ctx.getSocketFactory();
        } catch (GeneralSecurityException e) {
            throw new IOException("TLS is not available: " + e.getMessage(), e);
        }
    }

    private static String key(String host, int port) {
        return host.toLowerCase(Locale.ROOT) + ":" + port;
    }

    /** Pins the first certificate seen; ignores host names (the pin is the identity, as in ssh). */
    private static final class FirstUse extends X509ExtendedTrustManager {
        private final String server;
        private final Path file;
        private final Consumer<String> notices;
        /** The other servers of this one's list ({@code --server A,B}); empty for a single server. */
        private final List<String> group;

        FirstUse(String server, Path file, Consumer<String> notices, List<String> group) {
            this.server = server;
            this.file = file;
            this.notices = notices == null ? s -> { } : notices;
            this.group = group;
        }

        @Override
        public void checkServerTrusted(X509Certificate[] chain, String authType) throws CertificateException {
            if (chain == null || chain.length == 0) {
                throw new CertificateException("the server sent no certificate");
            }
            String offered = Fingerprint.of(chain[0]);
            synchronized (Tls.class) {
                List<String> lines;
                try {
                    lines = Files.exists(file) ? Files.readAllLines(file, StandardCharsets.UTF_8) : List.of();
                } catch (IOException e) {
                    throw new CertificateException("cannot read " + file + ": " + e.getMessage(), e);
                }
                for (int i = 0; i < lines.size(); i++) {
                    String[] w = lines.get(i).trim().split("\\s+");
                    if (w.length >= 2 && w[0].equals(server)) {
                        if (w[1].equals(offered)) {
                            return;
                        }
                        throw new ChangedCertificateException(changed(i + 1, w[1], offered));
                    }
                }
                Set<String> pinnedPeers = new LinkedHashSet<>();
                Set<String> peerNames = new LinkedHashSet<>();
                for (String line : lines) {
                    String[] w = line.trim().split("\\s+");
                    if (w.length >= 2 && group.contains(w[0])) {
                        pinnedPeers.add(w[1]);
                        peerNames.add(w[0]);
                    }
                }
                if (!pinnedPeers.isEmpty() && !pinnedPeers.contains(offered)) {
                    throw new UnpinnedStandbyException("The server " + server + " presents " + offered + ", a certificate not"
                            + " seen before, while " + String.join(", ", peerNames) + " of the same list is pinned in " + file
                            + ". Not trusting it on first use (someone could pose as the standby). Ask the server's operator"
                            + " for the fingerprint it prints at start and, if it is " + offered + ", add the line '" + server
                            + " " + offered + "' to " + file + "; or give both servers the same --tls-keystore.");
                }
                remember(offered);
            }
            notices.accept("The server " + server + " presents a certificate not seen before:\n  " + offered
                    + "\nTrusting it on first use and remembering it in " + file
                    + " (compare it with the fingerprint the server printed at its start).");
        }

        private String changed(int line, String remembered, String offered) {
            return String.join("\n",
                    "@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@",
                    "@    WARNING: THE SERVER'S CERTIFICATE HAS CHANGED!       @",
                    "@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@@",
                    "IT IS POSSIBLE THAT SOMEONE IS DOING SOMETHING NASTY: someone could be",
                    "listening in on you right now (a man-in-the-middle attack), or the server",
                    "was given a new certificate.",
                    "The certificate of " + server + " is " + offered + ",",
                    "but " + file + " line " + line + " remembers " + remembered + ".",
                    "Not connecting. If you know why it changed (ask the server's operator for the",
                    "fingerprint it prints at start), delete line " + line + " of " + file + " and connect again.");
        }

        private void remember(String offered) throws CertificateException {
            try {
                Path dir = file.toAbsolutePath().getParent();
                if (dir != null && !Files.isDirectory(dir)) {
                    Files.createDirectories(dir);
                }
                if (!Files.exists(file)) {
                    try {
                        Files.createFile(file, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
                    } catch (UnsupportedOperationException e) {
                        Files.createFile(file);
                    }
                }
                Files.writeString(file, server + " " + offered + "\n", StandardCharsets.UTF_8, StandardOpenOption.APPEND);
            } catch (IOException e) {
                throw new CertificateException("cannot remember the server's certificate in " + file + ": " + e.getMessage(), e);
            }
        }

        @Override
        public void checkServerTrusted(X509Certificate[] chain, String authType, Socket socket) throws CertificateException {
            checkServerTrusted(chain, authType);
        }

        @Override
        public void checkServerTrusted(X509Certificate[] chain, String authType, SSLEngine engine) throws CertificateException {
            checkServerTrusted(chain, authType);
        }

        // A client takes no connections, so it trusts no client, however it is asked.
        @Override
        public void checkClientTrusted(X509Certificate[] chain, String authType) throws CertificateException {
            throw notAServer();
        }

        @Override
        public void checkClientTrusted(X509Certificate[] chain, String authType, Socket socket) throws CertificateException {
            throw notAServer();
        }

        @Override
        public void checkClientTrusted(X509Certificate[] chain, String authType, SSLEngine engine) throws CertificateException {
            throw notAServer();
        }

        private static CertificateException notAServer() {
            return new CertificateException("a client does not take connections");
        }

        @Override
        public X509Certificate[] getAcceptedIssuers() {
            return new X509Certificate[0];
        }
    }
}
