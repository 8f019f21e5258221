package org.ripv.service;

import java.rmi.ConnectIOException;
import java.time.Duration;
import org.ripv.probe.PortProbe;

/** A service's --server that names a port where no RMI registry answers: which port it is, and what to give instead. */
final class WrongRegistryPort {
    private WrongRegistryPort() {}

    /** True when what answered at the registry's address does not speak RMI at all (JRMP). */
    static boolean notARegistry(Exception e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof ConnectIOException && String.valueOf(t.getMessage()).contains("non-JRMP")) {
                return true;
            }
        }
        return false;
    }

    /** What --server's port is, when it is not an RMI registry, and which port to give instead. */
    static String explain(String host, int registryPort) {
        String where = host + ":" + registryPort;
        PortProbe.Finding f = PortProbe.identify(host, registryPort, Duration.ofSeconds(3));
        String is = switch (f) {
            case RIPV_CLIENT_PORT, RIPV_CLIENT_PORT_PLAIN -> "RIPV's client port (where the CLI and the GUI log in)";
            case HTTP -> "the server's web/landing page port";
            default -> "not an RMI registry: " + f.what();
        };
        return where + " is " + is + ", not the server's RMI registry: give --server " + host
                + ":REGPORT with its registry port (1099 unless the server was started with --registry-port;"
                + " it prints 'services register at HOST:PORT')";
    }
}
