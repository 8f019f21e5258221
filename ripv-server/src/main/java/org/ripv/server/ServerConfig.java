package org.ripv.server;

import java.nio.file.Path;
import java.time.Duration;
import java.util.function.Consumer;
import javax.net.ssl.SSLContext;
import org.ripv.server.security.SecuritySettings;
import org.ripv.server.store.StoreLocation;
import org.ripv.wire.FrameCodec;

/**
 * Everything a {@link RIPVServer} is started with. Port 0 picks a free port (tests); an HTTP
 * port of -1 turns the landing page off.
 *
 * @param bindAddress    the address the client port, registry and landing page listen on (null: all)
 * @param port           the client socket port (4444)
 * @param registryPort   the RMI registry port (1099)
 * @param httpPort       the landing page port (8080), or -1 for none
 * @param dataDir        holds upload/, download/, permit.txt, service.secret
 * @param permitFile     the permit file (default DATA/permit.txt)
 * @param requestTimeout how long a request may go without any reply before it fails with TIMEOUT
 * @param serviceCheck   how often registered services are checked for life
 * @param maxUpload      the largest file a client may upload
 * @param maxFrame       the largest socket frame
 * @param maxClients     how many clients may be connected at once
 * @param tls            a TLS context for the client port, or null for plain TCP
 * @param clientJar      the client jar the landing page offers, or null
 * @param security       log-in deadline, per-address and brute-force limits, TLS on or off (docs/security.md)
 * @param stateStore     where transcripts, workflow queues and receipts, subscriptions and the audit trail are
 *                       kept: embedded (files in the data directory) or PostgreSQL (docs/operations.md)
 */
public record ServerConfig(String bindAddress, int port, int registryPort, int httpPort, Path dataDir, Path permitFile,
                           Duration requestTimeout, Duration serviceCheck, long maxUpload, int maxFrame, int maxClients,
                           SSLContext tls, Path clientJar,
                           SecuritySettings security,
                           StoreLocation stateStore) {

    public static final int DEFAULT_PORT = 4444;
    public static final int DEFAULT_REGISTRY_PORT = 1099;
    public static final int DEFAULT_HTTP_PORT = 8080;

    public ServerConfig {
        if (permitFile == null) {
            permitFile = dataDir.resolve("permit.txt");
        }
        if (security == null) {
            security = SecuritySettings.defaults();
        }
        if (stateStore == null) {
            stateStore = StoreLocation.embedded();
        }
    }

    /** Defaults for a data directory. */
    public static ServerConfig defaults(Path dataDir) {
        return new ServerConfig(null, DEFAULT_PORT, DEFAULT_REGISTRY_PORT, DEFAULT_HTTP_PORT, dataDir, null,
                Duration.ofSeconds(60), Duration.ofSeconds(3), 256L * 1024 * 1024,
                FrameCodec.DEFAULT_MAX_FRAME, 1000, null, null, null, null);
    }

    /** Defaults for tests: free ports, no landing page, short checks. */
    public static ServerConfig forTests(Path dataDir) {
        return defaults(dataDir).withPorts(0, 0, -1).withServiceCheck(Duration.ofMillis(500));
    }

    public ServerConfig withPorts(int clientPort, int registry, int http) {
        return with(d -> {
            d.port = clientPort;
            d.registryPort = registry;
            d.httpPort = http;
        });
    }

    public ServerConfig withRequestTimeout(Duration t) {
        return with(d -> d.requestTimeout = t);
    }

    public ServerConfig withServiceCheck(Duration t) {
        return with(d -> d.serviceCheck = t);
    }

    public ServerConfig withMaxUpload(long bytes) {
        return with(d -> d.maxUpload = bytes);
    }

    public ServerConfig withPermitFile(Path file) {
        return with(d -> d.permitFile = file);
    }

    public ServerConfig withTls(SSLContext context) {
        return with(d -> d.tls = context);
    }

    public ServerConfig withClientJar(Path jar) {
        return with(d -> d.clientJar = jar);
    }

    public ServerConfig withBindAddress(String address) {
        return with(d -> d.bindAddress = address);
    }

    public ServerConfig withSecurity(SecuritySettings s) {
        return with(d -> d.security = s);
    }

    public ServerConfig withMaxClients(int n) {
        return with(d -> d.maxClients = n);
    }

    /** Where the server keeps its state: embedded (the default) or a PostgreSQL database ({@code --state-db}). */
    public ServerConfig withStateStore(StoreLocation where) {
        return with(d -> d.stateStore = where);
    }

    /** A copy with what {@code change} sets changed: the one place that lists every component. */
    private ServerConfig with(Consumer<Draft> change) {
        Draft d = new Draft(this);
        change.accept(d);
        return new ServerConfig(d.bindAddress, d.port, d.registryPort, d.httpPort, dataDir, d.permitFile,
                d.requestTimeout, d.serviceCheck, d.maxUpload, maxFrame, d.maxClients, d.tls, d.clientJar,
                d.security, d.stateStore);
    }

    /** The components a wither may change, copied from a configuration. */
    private static final class Draft {
        String bindAddress;
        int port;
        int registryPort;
        int httpPort;
        Path permitFile;
        Duration requestTimeout;
        Duration serviceCheck;
        long maxUpload;
        int maxClients;
        SSLContext tls;
        Path clientJar;
        SecuritySettings security;
        StoreLocation stateStore;

        Draft(ServerConfig c) {
            bindAddress = c.bindAddress;
            port = c.port;
            registryPort = c.registryPort;
            httpPort = c.httpPort;
            permitFile = c.permitFile;
            requestTimeout = c.requestTimeout;
            serviceCheck = c.serviceCheck;
            maxUpload = c.maxUpload;
            maxClients = c.maxClients;
            tls = c.tls;
            clientJar = c.clientJar;
            security = c.security;
            stateStore = c.stateStore;
        }
    }

    /** Plain TCP on the client port and the landing page, for a test lab ({@code --plain}). */
    public ServerConfig plain() {
        return withSecurity(security.withPlain(true));
    }

}
