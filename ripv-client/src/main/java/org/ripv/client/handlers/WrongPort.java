package org.ripv.client.handlers;

import java.io.IOException;
import java.time.Duration;
import org.ripv.probe.PortProbe;

/**
 * Says why a connection that was made did not become a RIPV session: the port belongs to the
 * server's RMI registry or its landing page, or the server and the client disagree on TLS. It
 * asks the port what it is ({@link PortProbe}) and names the port to use instead.
 */
final class WrongPort {
    /** How long each of the probe's questions may wait. */
    static final Duration STEP = Duration.ofSeconds(3);

    private WrongPort() {
    }

    /** The failure {@code e} on {@code host:port} explained, or as it was when the probe finds nothing better to say. */
    static IOException explain(String host, int port, boolean tls, IOException e) {
        String where = host + ":" + port;
        String what = switch (PortProbe.identify(host, port, STEP)) {
            case RMI_REGISTRY -> where + " is the server's Java RMI registry, where services register, not its client port:"
                    + " connect to the client port instead (4444 unless the server was started with --port;"
                    + " it prints 'RIPVServer ready: clients on port N')";
            case HTTP -> where + " is the server's web/landing page port (it answers HTTP), not its client port: open it in a browser,"
                    + " or connect the CLI and the GUI to the client port (4444 unless the server was started with --port;"
                    + " it prints 'RIPVServer ready: clients on port N')";
            case RIPV_CLIENT_PORT_PLAIN -> tls ? where + " is a RIPV client port without TLS (the server was started with --plain):"
                    + " connect with --plain too, on a network you trust" : null;
            case RIPV_CLIENT_PORT -> tls ? null : where + " is a RIPV client port with TLS: leave out --plain";
            case NOTHING -> "nothing listens on " + where + " any more (the connection was refused): is the server running?";
            case SILENT -> null;
        };
        return what == null ? e : new IOException(what + " [" + e.getMessage() + "]", e);
    }
}
