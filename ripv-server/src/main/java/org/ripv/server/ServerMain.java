package org.ripv.server;

import java.io.BufferedReader;
import java.io.Console;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.function.Consumer;
import javax.net.ssl.SSLContext;
import org.ripv.naming.Handles;
import org.ripv.rmi.RmiDeadlineOptions;
import org.ripv.rmi.RmiSupport;
import org.ripv.server.demo.WebhookSink;
import org.ripv.server.lock.DataDirLock;
import org.ripv.server.notify.Smtp;
import org.ripv.server.notify.NotifyOptions;
import org.ripv.server.permit.Passwords;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.security.SelfSignedTls;
import org.ripv.server.security.TlsOptions;
import org.ripv.server.standby.StandbyLoop;
import org.ripv.server.standby.StandbyOptions;
import org.ripv.server.store.StateStoreOptions;
import org.ripv.server.web.WebOptions;
import org.ripv.service.ServiceOptions;
import org.ripv.launch.Launchers;
import org.ripv.launch.OptionChecks;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code ripv server} and {@code ripv passwd}. Exit codes: 0 done, 1 failed to start or failed,
 * 2 bad command line; a server stopped by Ctrl-C or SIGTERM ends as the JVM does (130, 143)
 * after stopping cleanly.
 */
@Command(name = "ripv", mixinStandardHelpOptions = true,
        description = "The RIPV broker, and its user administration.",
        subcommands = {ServerMain.Serve.class, ServerMain.Passwd.class, WebhookSink.class})
public final class ServerMain implements Callable<Integer> {
    /**
     * The JVM options {@code ./ripv server} launches the server with (the {@code ripv} script
     * says them again; {@code RipvServerJvmTest} holds the two to one list), and so the
     * benchmarks that start a server: the parallel collector. The broker's live heap is small and
     * nearly all it allocates dies young (a frame's few hundred bytes of Jetty's objects per page
     * per console line); G1's write barriers and its refinement and marking threads cost the web
     * fan-out about a fifth of its CPU per delivery, the parallel collector's young collections a
     * small part of that (issue 38, docs/performance.md "The web console").
     */
    public static final java.util.List<String> JVM_OPTIONS = java.util.List.of("-XX:+UseParallelGC");


    @Override
    public Integer call() {
        return run("server");
    }

    @Command(name = "server", mixinStandardHelpOptions = true,
            description = "Runs the RIPVServer: clients on --port, services register in the RMI registry on --registry-port.")
    static final class Serve implements Callable<Integer> {
        @Option(names = "--port", defaultValue = "4444", description = "Client port (default ${DEFAULT-VALUE}).")
        int port;
        @Option(names = "--registry-port", defaultValue = "1099", description = "RMI registry port (default ${DEFAULT-VALUE}).")
        int registryPort;
        @Option(names = "--http-port", defaultValue = "8080", description = "Landing page port; 0 turns it off (default ${DEFAULT-VALUE}).")
        int httpPort;
        @Option(names = "--data", description = "Data directory: upload/, download/, permit.txt, service.secret (default $RIPV_DATA or ~/.ripv/server).")
        Path data;
        @Option(names = "--permit", description = "The permit file (default DATA/permit.txt).")
        Path permit;
        @Option(names = "--bind", description = "Listen only on this address (default: all).")
        String bind;
        @Option(names = "--rmi-hostname", description = "The name services use to call this server back (sets java.rmi.server.hostname).")
        String rmiHostname;
        @Option(names = "--request-timeout", defaultValue = "60", description = "Seconds a request may wait without any reply (default ${DEFAULT-VALUE}).")
        long requestTimeout;
        @Option(names = "--max-upload", defaultValue = "268435456", description = "Largest upload in bytes (default ${DEFAULT-VALUE}).")
        long maxUpload;
        @Option(names = "--max-clients", defaultValue = "1000", paramLabel = "N",
                description = "Clients that may be logged in at once (default ${DEFAULT-VALUE}; each idle one costs the server a thread"
                        + " and its buffers: docs/performance.md, Connections).")
        int maxClients;
        @Option(names = "--login-deadline", defaultValue = "10", description = "Seconds a connection may take to log in (default ${DEFAULT-VALUE}).")
        long loginDeadline;
        @Option(names = "--outbound-port", defaultValue = "4446", paramLabel = "PORT",
                description = "Port for services in outbound-only mode (behind NAT: they connect out and the server's calls come back"
                        + " over that connection); 0: any free port, -1: none (default ${DEFAULT-VALUE}). A busy port only warns.")
        int outboundPort;
        @Mixin
        RmiDeadlineOptions deadlines = new RmiDeadlineOptions();
        @Option(names = "--client-jar", description = "The client jar the landing page offers (default: ripv-client.jar beside this jar).")
        Path clientJar;
        @Option(names = "--transcript-days", defaultValue = "90", description = "Days of vehicle transcripts to keep (default ${DEFAULT-VALUE}).")
        int transcriptDays;
        @Option(names = "--transcript-file-mb", defaultValue = "64", description = "A transcript file is continued in a new one past this size (default ${DEFAULT-VALUE} MB).")
        long transcriptFileMb;
        @Mixin
        WebOptions web = new WebOptions();
        @Mixin
        TlsOptions tls = new TlsOptions();
        @Mixin
        NotifyOptions notify = new NotifyOptions();
        @Mixin
        StateStoreOptions stateStore = new StateStoreOptions();
        @Mixin
        StandbyOptions standby = new StandbyOptions();
        private volatile int openedOutbound = -1;

        @Override
        public Integer call() throws Exception {
            if (rmiHostname != null) {
                System.setProperty("java.rmi.server.hostname", rmiHostname);
            } else if (bind != null) {
                // Stubs must name an address the server actually listens on.
                System.setProperty("java.rmi.server.hostname", bind);
            }
            try {
                deadlines.apply();
                OptionChecks.atLeast("--max-clients", maxClients, 1);
                web.checkPages();
            } catch (IllegalArgumentException e) {
                throw new CommandLine.ParameterException(new CommandLine(this), e.getMessage());
            }
            Path dataDir = data != null ? data : ServiceOptions.defaultDataDir();
            ServerConfig config = ServerConfig.defaults(dataDir)
                    .withPorts(port, registryPort, httpPort == 0 ? -1 : httpPort)
                    .withRequestTimeout(Duration.ofSeconds(requestTimeout))
                    .withMaxUpload(maxUpload)
                    .withPermitFile(permit)
                    .withBindAddress(bind)
                    .withMaxClients(maxClients)
                    .withClientJar(clientJar != null ? clientJar : defaultClientJar());
            config = config.withSecurity(web.applyTo(config.security().withPlain(tls.plain())
                    .withLoginDeadline(Duration.ofSeconds(loginDeadline))));
            try {
                tls.check();
            } catch (IllegalArgumentException e) {
                throw new CommandLine.ParameterException(new CommandLine(this), e.getMessage());
            }
            SelfSignedTls.Identity id = tls.identity();
            String fingerprint = null;
            if (id != null) {
                config = config.withTls(id.context());
                fingerprint = id.fingerprint();
            }
            SessionOptions sessions;
            try {
                web.checkTilesAndPublic();
                config = config.withStateStore(stateStore.location(System.err));
                sessions = SessionOptions.defaults().withTranscripts(transcriptFileMb * 1024 * 1024, transcriptDays)
                        .withWebhooks(notify.webhooks());
                Smtp smtp = notify.smtp();
                if (smtp != null) {
                    sessions = sessions.withSmtp(smtp);
                }
            } catch (IllegalArgumentException e) {
                System.err.println("Error: " + e.getMessage());
                return 2;
            }
            // Held until this JVM ends (the OS lets go of it however the process ends).
            DataDirLock dirLock;
            try {
                dirLock = DataDirLock.acquire(dataDir);
            } catch (DataDirLock.HeldException e) {
                System.err.println("Error: " + e.getMessage());
                return 1;
            }
            RmiSupport.filterProcess();
            ServerConfig cfg = config;
            SessionOptions opts = sessions;
            String tlsFingerprint = fingerprint;
            StandbyLoop.Opener<RIPVServer> open = () -> open(cfg, opts);
            Consumer<RIPVServer> ready = s -> ready(s, cfg, tlsFingerprint);
            if (!config.stateStore().isEmbedded()) {
                // A hot standby: serve only while holding the lead in the state database.
                String me = (bind != null ? bind : rmiHostname != null ? rmiHostname : Handles.localHost()) + ":" + port;
                var loop = new StandbyLoop<>(standby.leads(config.stateStore(), me), open, ready);
                Runtime.getRuntime().addShutdownHook(new Thread(loop::stop, "ripv-server-shutdown"));
                System.err.println("RIPVServer on " + me + ": taking the lead in " + config.stateStore()
                        + " (standing by while another server holds it)");
                loop.run();
                return 0;
            }
            RIPVServer server = open.open();
            CountDownLatch stopped = new CountDownLatch(1);
            Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                server.stop();
                closeQuietly(dirLock);
                stopped.countDown();
            }, "ripv-server-shutdown"));
            ready.accept(server);
            stopped.await();
            return 0;
        }

        private static void closeQuietly(DataDirLock lock) {
            try {
                lock.close();
            } catch (IOException e) {
                // the process is ending: the OS lets go of the lock anyway
            }
        }

        /** Starts a server and its outbound port (a busy one only warns). */
        private RIPVServer open(ServerConfig config, SessionOptions sessions) throws IOException {
            RIPVServer server = new RIPVServer(config, sessions).withMapTiles(web.mapTiles()).withPublicView(web.publicNames());
            server.start();
            openedOutbound = -1;
            if (outboundPort >= 0) {
                try {
                    openedOutbound = server.openOutbound(outboundPort);
                } catch (IOException e) {
                    System.err.println("Warning: " + e.getMessage() + "; services in --outbound-only mode cannot connect");
                }
            }
            return server;
        }

        /** The "ready" lines, each time a server starts serving. */
        private void ready(RIPVServer server, ServerConfig config, String fingerprint) {
            String outbound = openedOutbound > 0 ? ", services behind NAT connect out to port " + openedOutbound : "";
            try {
                PermitFile p = PermitFile.load(config.permitFile());
                if (p.users().isEmpty()) {
                    System.err.println("No users yet: add one with  ripv passwd --permit " + config.permitFile() + " USER --roles operators");
                }
            } catch (IOException e) {
                System.err.println("Warning: cannot read the permit file " + config.permitFile() + ": " + e.getMessage());
            }
            if (fingerprint == null) {
                fingerprint = server.tlsFingerprint();
            }
            System.err.println("RIPVServer ready: clients on port " + server.port() + (tls.plain() ? " (plain TCP, no TLS)" : " (TLS)")
                    + ", services register at " + (bind != null ? bind : "this host") + ":" + server.registryPort()
                    + " with --secret-file " + server.secretFile()
                    + (server.httpPort() > 0 ? ", landing page on " + (tls.plain() ? "http" : "https") + "://localhost:" + server.httpPort() + "/" : "")
                    + outbound);
            if (fingerprint != null) {
                System.err.println("TLS certificate fingerprint: " + fingerprint
                        + "\n  (clients show it when they first connect; compare before trusting)");
            }
        }

        private static Path defaultClientJar() {
            try {
                Path self = Path.of(ServerMain.class.getProtectionDomain().getCodeSource().getLocation().toURI());
                Path dir = self.getParent();
                for (Path candidate : List.of(dir.resolve("ripv-client.jar"), dir.resolve("../../ripv-client/target/ripv-client.jar"))) {
                    if (Files.isRegularFile(candidate)) {
                        return candidate.normalize();
                    }
                }
            } catch (Exception ignored) {
                // no jar to offer
            }
            return null;
        }
    }

    @Command(name = "passwd", mixinStandardHelpOptions = true,
            description = "Adds a user to the permit file or changes a user's password. Asks on the terminal, "
                    + "or reads the password from the first line of standard input when there is none.")
    static final class Passwd implements Callable<Integer> {
        @Option(names = "--permit", required = true, description = "The permit file (created if missing).")
        Path permit;
        @Option(names = "--roles", split = ",", description = "Roles, e.g. operators or observers,db-reader (kept if not given).")
        List<String> roles;
        @Option(names = "--iterations", defaultValue = "" + Passwords.DEFAULT_ITERATIONS, hidden = true)
        int iterations;
        @Parameters(index = "0", description = "The user name.")
        String user;
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @Override
        public Integer call() throws IOException {
            PrintWriter err = spec.commandLine().getErr();
            char[] password = readPassword(err);
            if (password.length < 8) {
                err.println("Error: a password needs at least 8 characters");
                return 1;
            }
            boolean existed = Files.exists(permit) && PermitFile.load(permit).user(user).isPresent();
            PermitFile.setUser(permit, user, password, roles, iterations);
            if (!existed && (roles == null || roles.isEmpty())) {
                err.println("Warning: '" + user + "' has no roles; only rules that name the user will allow anything"
                        + " (give --roles operators, or observers)");
            }
            Arrays.fill(password, '\0');
            spec.commandLine().getOut().println("set the password of '" + user + "' in " + permit
                    + (roles == null ? "" : " with roles " + String.join(",", roles)));
            return 0;
        }

        private static char[] readPassword(PrintWriter err) throws IOException {
            Console console = System.console();
            if (console != null) {
                char[] a = console.readPassword("New password: ");
                char[] b = console.readPassword("Again: ");
                if (a == null || b == null || !Arrays.equals(a, b)) {
                    throw new IOException("the two passwords differ");
                }
                return a;
            }
            String line = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8)).readLine();
            if (line == null) {
                throw new IOException("no password on standard input");
            }
            return line.toCharArray();
        }
    }

    /** A TLS context for {@link ServerConfig#withTls} from a PKCS12 key store and its password file. */
    public static SSLContext tlsContext(Path keystore, Path passwordFile) throws Exception {
        return TlsOptions.identity(keystore, passwordFile).context();
    }

    /** Runs the command line; returns the exit code. */
    public static int run(String... args) {
        // The thesis form: java -jar ripv-server.jar 4444
        if (args.length == 1 && args[0].matches("\\d{1,5}")) {
            args = new String[] {"server", "--port", args[0]};
        }
        CommandLine cl = Launchers.commandLine(new ServerMain(), "ripv");
        return cl.execute(args);
    }

    public static void main(String[] args) {
        // Before anything makes an object stream: the JVM takes a filter factory only until then.
        RmiSupport.filterProcess();
        System.exit(run(args));
    }
}
