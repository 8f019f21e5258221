package org.ripv.service;

import java.io.IOException;
import java.io.PrintStream;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.NetworkInterface;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import org.ripv.failover.ServerList;
import org.ripv.naming.Handles;
import org.ripv.rmi.RmiDeadlineOptions;
import org.ripv.rmi.RmiSupport;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * The command-line options every service launcher shares (picocli mixin):
 * {@code --server HOST[:REGPORT] [--secret-file F] [--host NAME] [--export-port N] [--retry-forever]}.
 */
public final class ServiceLaunchOptions {
    @Option(names = "--server", required = true, paramLabel = "HOST[:REGPORT][,HOST2[:REGPORT]]",
            description = "The RIPVServer to register with (RMI registry port 1099 unless given). //HOST works too."
                    + " Several, comma-separated: an active server and its standbys; the service registers with whichever answers.")
    String server;

    @Option(names = "--secret-file", paramLabel = "FILE",
            description = "The server's service secret (DATA/service.secret). Else $RIPV_SERVICE_SECRET, else ~/.ripv/server/service.secret.")
    Path secretFile;

    @Option(names = "--host", paramLabel = "NAME",
            description = "The host name to register under and that the server calls back (sets java.rmi.server.hostname). Default: this machine's name.")
    String host;

    @Option(names = "--bind", paramLabel = "ADDRESS",
            description = "The address this service's RMI object listens on. Default: the address this host uses to reach"
                    + " the server (127.0.0.1 for a server on this machine); with --host, every interface. * for every interface.")
    String bind;

    @Option(names = "--retry-forever", description = "Keep trying to register when the server does not accept the secret or"
            + " --server names a port that is not its RMI registry (default: give up with an error after "
            + ServiceLaunchOptions.TRIES + " tries). A server that is not up yet is waited for in any case.")
    boolean retryForever;

    /** Registrations in a row that a retry cannot mend before a launched service gives up. */
    static final int TRIES = 5;

    /** Where launch messages go (standard error; injectable for tests). */
    PrintStream err = System.err;

    @Option(names = "--export-port", paramLabel = "PORT", defaultValue = "0",
            description = "The port this service's RMI object listens on (default: any free port; fix it for firewalls).")
    int exportPort;

    @Option(names = "--outbound-only", arity = "0..1", fallbackValue = "" + ServiceOptions.DEFAULT_OUTBOUND_PORT,
            defaultValue = "-1", paramLabel = "PORT",
            description = "Behind NAT or a firewall: only connect out, to the server's outbound port (default "
                    + ServiceOptions.DEFAULT_OUTBOUND_PORT + "); the server's calls come back over that connection. Nothing listens here.")
    int outboundPort;

    @Mixin
    RmiDeadlineOptions deadlines = new RmiDeadlineOptions();

    /** Applies {@code --host} to RMI and naming; call before creating the service. */
    public String hostName() {
        if (host != null && !host.isBlank()) {
            System.setProperty("java.rmi.server.hostname", host);
            System.setProperty("ripv.host", host);
            return host;
        }
        return Handles.localHost();
    }

    /**
     * Accepts the thesis's form {@code SerialPortServer //host}: when no {@code --server} is
     * given, the first {@code //host} argument becomes {@code --server host}. Launchers pass
     * their arguments through this before parsing, since {@code --server} is required.
     */
    public static String[] thesisForm(String[] args) {
        List<String> out = new ArrayList<>(List.of(args));
        boolean hasServer = out.stream().anyMatch(a -> a.equals("--server") || a.startsWith("--server="));
        if (!hasServer) {
            for (int i = 0; i < out.size(); i++) {
                if (out.get(i).startsWith("//")) {
                    out.set(i, out.get(i).substring(2));
                    out.add(i, "--server");
                    break;
                }
            }
        }
        return out.toArray(String[]::new);
    }

    /** The server option, for launchers that accept the thesis's positional {@code //host}. */
    public void server(String value) {
        this.server = value;
    }

    /**
     * Runs a service until the process is stopped: registers it (retrying while the server is
     * away), stops it cleanly on Ctrl-C, and returns 1 with an {@code Error:} line when the server
     * refuses it for good. What every service launcher's {@code call()} returns.
     */
    public int serve(RIPVService service) throws Exception {
        if (!RmiSupport.filterProcess()) {
            err.println("Warning: RMI replies in this process are not filtered: an object stream was made before the"
                    + " launcher could install RIPV's filter factory (call RmiSupport.filterProcess() first in main)");
        }
        applyBind();
        ServiceConnector connector = ServiceConnector.connect(service, toOptions());
        connector.onNotice(err::println);
        AtomicBoolean stopping = new AtomicBoolean();
        Thread hook = new Thread(() -> {
            stopping.set(true);
            service.stop();    // first: running commands end and the last replies reach the server
            connector.close(); // then withdraw from RMI
        }, "ripv-service-shutdown");
        Runtime.getRuntime().addShutdownHook(hook);
        err.println(service.name() + " (SID " + service.sid() + ") serving; registering with " + server
                + (outboundPort > 0 ? " (outbound only, port " + outboundPort + ")" : ""));
        String why = connector.awaitFailure();
        if (stopping.get()) {
            return 0; // Ctrl-C or SIGTERM: the hook is stopping everything
        }
        Runtime.getRuntime().removeShutdownHook(hook);
        service.stop();
        connector.close();
        err.println("Error: " + why);
        return 1;
    }

    /**
     * Chooses where this service listens ({@link org.ripv.rmi.RmiSupport#BIND_PROPERTY}): {@code --bind},
     * else the local address that reaches the server, so that a service for a server on this
     * machine is not reachable from any other. The server calls back to that address unless
     * {@code --host} names another.
     */
    void applyBind() throws IOException {
        String address = bind;
        if (address == null && (host == null || host.isBlank())) {
            address = routeTo(ServerList.parse(server, ServiceOptions.DEFAULT_REGISTRY_PORT).first().host())
                    .getHostAddress();
        }
        if (address == null || address.isBlank() || address.equals("*")) {
            return;
        }
        System.setProperty(RmiSupport.BIND_PROPERTY, address);
        if (host == null || host.isBlank()) {
            System.setProperty("java.rmi.server.hostname", address);
        }
    }

    /** The local address packets to {@code serverHost} leave from: loopback for this machine. */
    static InetAddress routeTo(String serverHost) throws IOException {
        InetAddress server = InetAddress.getByName(serverHost);
        if (server.isLoopbackAddress() || NetworkInterface.getByInetAddress(server) != null) {
            return InetAddress.getLoopbackAddress();
        }
        try (DatagramSocket probe = new DatagramSocket()) {
            probe.connect(server, 9); // no packet is sent: this only asks the routing table
            InetAddress local = probe.getLocalAddress();
            return local == null || local.isAnyLocalAddress() ? InetAddress.getLoopbackAddress() : local;
        }
    }

    public ServiceOptions toOptions() throws IOException {
        ServerList servers = ServerList.parse(server, ServiceOptions.DEFAULT_REGISTRY_PORT);
        if (outboundPort == 0 || outboundPort > 65535 || outboundPort < -1) {
            throw new IllegalArgumentException("--outbound-only takes the server's outbound port, 1 to 65535, not " + outboundPort);
        }
        deadlines.apply();
        return new ServiceOptions(servers.first().host(), servers.first().port(), ServiceOptions.resolveSecret(secretFile),
                exportPort, Duration.ofSeconds(3), outboundPort).withServers(servers).givingUpAfter(retryForever ? 0 : TRIES);
    }
}
