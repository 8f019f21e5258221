package org.ripv.services.database;

import java.net.InetAddress;
import java.util.concurrent.locks.LockSupport;
import org.apache.derby.drda.NetworkServerControl;
import org.ripv.probe.FreePorts;

/** A real Derby network server (derbynet) on a free loopback port, for tests. */
final class DerbyNetwork implements AutoCloseable {
    private final NetworkServerControl control;
    private final int port;

    private DerbyNetwork(NetworkServerControl control, int port) {
        this.control = control;
        this.port = port;
    }

    static DerbyNetwork start() throws Exception {
        int port = FreePorts.one();
        NetworkServerControl control = new NetworkServerControl(InetAddress.getLoopbackAddress(), port);
        control.start(null);
        // start() returns before the server listens and Derby offers no "started" callback:
        // ping it a bounded number of times (5 s at most).
        for (int i = 0; ; i++) {
            try {
                control.ping();
                break;
            } catch (Exception e) {
                if (i == 50) {
                    throw e;
                }
                LockSupport.parkNanos(100_000_000L);
            }
        }
        return new DerbyNetwork(control, port);
    }

    int port() {
        return port;
    }

    /** A client URL for a database on this server, e.g. {@code url("memory:x")}. */
    String url(String database) {
        return "jdbc:derby://localhost:" + port + "/" + database;
    }

    @Override
    public void close() throws Exception {
        control.shutdown();
    }
}
