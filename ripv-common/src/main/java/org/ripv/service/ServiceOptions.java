package org.ripv.service;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;
import org.ripv.failover.ServerList;

/**
 * Where a service finds its server and how it proves it may register.
 *
 * @param serverHost   the RIPVServer's host
 * @param registryPort the server's RMI registry port (1099 by default)
 * @param secret       the server's service secret
 * @param exportPort   the port this service's RMI object listens on (0: any free port)
 * @param heartbeat    how often the service checks in, and retries when the server is away
 * @param outboundPort the server's outbound-service port when the service only connects out
 *                     (NAT, firewalls: {@code --outbound-only}), or -1 for plain RMI both ways
 * @param servers      every server to try, the first being {@code serverHost:registryPort}: an
 *                     active server and its standbys ({@code --server host1,host2}); null for that one only
 * @param giveUpAfter  how many registrations in a row a retry cannot mend (a server that does not
 *                     accept the secret, a port that is not an RMI registry) end the service's tries;
 *                     0: it keeps trying (the launchers give up after 5 unless {@code --retry-forever})
 */
public record ServiceOptions(String serverHost, int registryPort, String secret, int exportPort, Duration heartbeat,
                             int outboundPort, ServerList servers, int giveUpAfter) {
    public static final int DEFAULT_REGISTRY_PORT = 1099;
    /** The server's port for services in outbound-only mode. */
    public static final int DEFAULT_OUTBOUND_PORT = 4446;

    /** Plain RMI both ways. */
    public ServiceOptions(String serverHost, int registryPort, String secret, int exportPort, Duration heartbeat) {
        this(serverHost, registryPort, secret, exportPort, heartbeat, -1);
    }

    /** One server, outbound-only when {@code outboundPort} is positive. */
    public ServiceOptions(String serverHost, int registryPort, String secret, int exportPort, Duration heartbeat,
                          int outboundPort) {
        this(serverHost, registryPort, secret, exportPort, heartbeat, outboundPort, null, 0);
    }

    /** The same, connecting out only, to the server's outbound port. */
    public ServiceOptions outboundOnly(int port) {
        return new ServiceOptions(serverHost, registryPort, secret, exportPort, heartbeat, port, servers, giveUpAfter);
    }

    /** The same with a list of servers to try in turn (an active server and its standbys); the first becomes serverHost. */
    public ServiceOptions withServers(ServerList list) {
        return new ServiceOptions(list.first().host(), list.first().port(), secret, exportPort, heartbeat, outboundPort, list,
                giveUpAfter);
    }

    /** The same, giving up after {@code tries} registrations in a row that a retry cannot mend (0: never). */
    public ServiceOptions givingUpAfter(int tries) {
        return new ServiceOptions(serverHost, registryPort, secret, exportPort, heartbeat, outboundPort, servers, tries);
    }

    /** True in outbound-only mode. */
    public boolean outbound() {
        return outboundPort > 0;
    }
    /** The environment variable a service may read its secret from. */
    public static final String SECRET_ENV = "RIPV_SERVICE_SECRET";

    public ServiceOptions {
        Objects.requireNonNull(serverHost, "serverHost");
        Objects.requireNonNull(secret, "secret");
        heartbeat = heartbeat == null ? Duration.ofSeconds(3) : heartbeat;
        if (giveUpAfter < 0) {
            throw new IllegalArgumentException("giveUpAfter is a number of tries, 0 for never, not " + giveUpAfter);
        }
        servers = servers == null ? ServerList.of(serverHost, registryPort) : servers;
    }

    public static ServiceOptions of(String serverHost, int registryPort, String secret) {
        return new ServiceOptions(serverHost, registryPort, secret, 0, Duration.ofSeconds(3));
    }

    /**
     * Parses {@code HOST[:REGPORT]}, with the thesis's {@code //host} form accepted too.
     *
     * @return {host, port}
     */
    public static Object[] parseServer(String text) {
        String t = text.trim();
        if (t.startsWith("//")) {
            t = t.substring(2);
        }
        int port = DEFAULT_REGISTRY_PORT;
        int colon = t.lastIndexOf(':');
        if (colon > 0 && t.indexOf(':') == colon) {
            try {
                port = Integer.parseInt(t.substring(colon + 1));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("'" + text + "' is not HOST[:PORT]: the port is not a number");
            }
            t = t.substring(0, colon);
        }
        if (t.isEmpty() || port < 1 || port > 65535) {
            throw new IllegalArgumentException("'" + text + "' is not HOST[:PORT]");
        }
        return new Object[] {t, port};
    }

    /**
     * Finds the service secret: the file given, else {@code RIPV_SERVICE_SECRET}, else the
     * default server data directory's {@code service.secret} (a server on this machine).
     */
    public static String resolveSecret(Path secretFile) throws IOException {
        if (secretFile != null) {
            return read(secretFile);
        }
        String env = System.getenv(SECRET_ENV);
        if (env != null && !env.isBlank()) {
            return env.trim();
        }
        Path local = defaultDataDir().resolve("service.secret");
        if (Files.isReadable(local)) {
            return read(local);
        }
        throw new IOException("no service secret: give --secret-file FILE (the server's DATA/service.secret) or set "
                + SECRET_ENV);
    }

    private static String read(Path file) throws IOException {
        String s = Files.readString(file, StandardCharsets.UTF_8).trim();
        if (s.isEmpty()) {
            throw new IOException("the secret file " + file + " is empty");
        }
        return s;
    }

    /** The server's default data directory: {@code $RIPV_DATA}, else {@code ~/.ripv/server}. */
    public static Path defaultDataDir() {
        String env = System.getenv("RIPV_DATA");
        if (env != null && !env.isBlank()) {
            return Path.of(env);
        }
        return Path.of(System.getProperty("user.home"), ".ripv", "server");
    }
}
