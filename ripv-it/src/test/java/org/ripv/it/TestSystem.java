package org.ripv.it;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.Tls;
import org.ripv.server.RIPVServer;
import org.ripv.server.ServerConfig;
import org.ripv.server.permit.PermitFile;
import org.ripv.service.RIPVService;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;

/**
 * A whole RIPV system in one JVM for tests: a real RIPVServer on free ports in a temporary data
 * directory, services registered over real RMI, clients over real sockets.
 *
 * <pre>{@code
 * try (TestSystem sys = TestSystem.start(tempDir)) {
 *     sys.user("alice", "operators");
 *     sys.register(new ClockService("localhost"));
 *     ClientSocketHandler c = sys.login("alice");
 * }
 * }</pre>
 */
public final class TestSystem implements AutoCloseable {
    /** Every test user's password. */
    public static final String PASSWORD = "correct horse";

    private final Path dataDir;
    private final RIPVServer server;
    private final List<AutoCloseable> closeables = new ArrayList<>();

    private TestSystem(Path dataDir, RIPVServer server) {
        this.dataDir = dataDir;
        this.server = server;
    }

    public static TestSystem start(Path dir) throws IOException {
        return start(ServerConfig.forTests(dir.resolve("server")));
    }

    static {
        // Every test server is new: remember their certificates in a file of this JVM's own.
        if (System.getProperty(Tls.KNOWN_HOSTS_PROPERTY) == null) {
            try {
                Path f = Files.createTempFile("ripv-known-hosts", "");
                f.toFile().deleteOnExit();
                System.setProperty(Tls.KNOWN_HOSTS_PROPERTY, f.toString());
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        }
    }

    private static Path sharedTls;

    /**
     * Gives a new data directory the TLS key store made once for this JVM, as if the server had
     * made it on its first start (keytool takes a second; tests start many servers).
     */
    private static synchronized void seedTls(ServerConfig config) throws IOException {
        if (config.tls() != null || config.security().plain()) {
            return;
        }
        if (sharedTls == null) {
            Path dir = Files.createTempDirectory("ripv-test-tls");
            org.ripv.server.security.SelfSignedTls.loadOrCreate(dir);
            sharedTls = dir;
        }
        Path tls = config.dataDir().resolve("tls");
        if (!Files.exists(tls.resolve("server.p12"))) {
            Files.createDirectories(tls);
            for (String f : List.of("server.p12", "server.pass")) {
                Files.copy(sharedTls.resolve(f), tls.resolve(f), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            }
        }
    }

    public static TestSystem start(ServerConfig config) throws IOException {
        return start(config, org.ripv.server.SessionOptions.defaults());
    }

    /** A system whose server keeps vehicle sessions with these options (transcripts, SMTP, retries). */
    public static TestSystem start(ServerConfig config, org.ripv.server.SessionOptions sessions) throws IOException {
        seedTls(config);
        RIPVServer server = new RIPVServer(config, sessions);
        server.start();
        return new TestSystem(config.dataDir(), server);
    }

    public RIPVServer server() {
        return server;
    }

    public Path dataDir() {
        return dataDir;
    }

    public Path uploadDir() {
        return server.fileStore().uploadDir();
    }

    public Path downloadDir() {
        return server.fileStore().downloadDir();
    }

    /**
     * A file the server stored from a service: each MailBox's files live in a folder of their
     * own ({@code download/HANDLE/NAME}); this finds NAME in whichever folder holds it.
     */
    public Path downloaded(String name) throws IOException {
        Path top = downloadDir().resolve(name);
        if (Files.exists(top)) {
            return top;
        }
        try (var folders = Files.list(downloadDir())) {
            return folders.map(f -> f.resolve(name)).filter(Files::isRegularFile).findFirst().orElse(top);
        }
    }

    /** Adds a user with {@link #PASSWORD} (a cheap hash, for speed) and reloads the permit file. */
    public TestSystem user(String name, String... roles) throws IOException {
        PermitFile.setUser(dataDir.resolve("permit.txt"), name, PASSWORD.toCharArray(), List.of(roles), 1000);
        server.reloadPermits();
        return this;
    }

    /** Replaces the permit file's rules (users stay) and reloads. */
    public TestSystem rules(String... lines) throws IOException {
        Path p = dataDir.resolve("permit.txt");
        List<String> keep = new ArrayList<>();
        for (String l : Files.readAllLines(p, StandardCharsets.UTF_8)) {
            if (l.startsWith("user ")) {
                keep.add(l);
            }
        }
        keep.addAll(List.of(lines));
        Files.write(p, keep, StandardCharsets.UTF_8);
        server.reloadPermits();
        return this;
    }

    public String secret() throws IOException {
        return Files.readString(server.secretFile(), StandardCharsets.UTF_8).trim();
    }

    public ServiceOptions serviceOptions() throws IOException {
        return new ServiceOptions("localhost", server.registryPort(), secret(), 0, Duration.ofMillis(500));
    }

    /** Registers a service over RMI and waits until the server lists it. */
    public ServiceConnector register(RIPVService service) throws Exception {
        ServiceConnector c = ServiceConnector.connect(service, serviceOptions());
        closeables.add(service::stop);
        closeables.add(c);
        if (!c.awaitRegistered(Duration.ofSeconds(20))) {
            throw new IllegalStateException(service + " did not register");
        }
        return c;
    }

    /** A connection over TLS (trusting the test server on first use), or plain TCP to a --plain server. */
    public ClientSocketHandler connect() throws IOException {
        ClientSocketHandler c = isPlain() ? ClientSocketHandler.connectPlain("localhost", server.port())
                : ClientSocketHandler.connect("localhost", server.port());
        closeables.add(c);
        return c;
    }

    private boolean isPlain() {
        return server.tlsFingerprint() == null;
    }

    /** A raw socket to the client port (TLS unless the server is plain), for tests that write bytes by hand. */
    public java.net.Socket rawSocket() throws IOException {
        java.net.Socket s = isPlain() ? new java.net.Socket("localhost", server.port())
                : Tls.trustOnFirstUse("localhost", server.port(), Tls.defaultKnownHosts(), n -> { }).createSocket("localhost", server.port());
        closeables.add(s);
        return s;
    }

    /** The known-hosts file the test clients use. */
    public static Path knownHosts() {
        return Tls.defaultKnownHosts();
    }

    /** A client logged in as the user. */
    public ClientSocketHandler login(String user) throws Exception {
        ClientSocketHandler c = connect();
        c.login(user, PASSWORD.toCharArray());
        return c;
    }

    @Override
    public void close() {
        for (int i = closeables.size() - 1; i >= 0; i--) {
            try {
                closeables.get(i).close();
            } catch (Exception ignored) {
                // best effort
            }
        }
        server.stop();
    }
}
