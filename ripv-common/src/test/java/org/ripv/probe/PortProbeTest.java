package org.ripv.probe;

import static org.assertj.core.api.Assertions.assertThat;

import com.sun.net.httpserver.HttpServer;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.rmi.registry.LocateRegistry;
import java.rmi.registry.Registry;
import java.rmi.server.UnicastRemoteObject;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.ripv.wire.FrameCodec;

/** The probe against the real thing of each kind, each on a free port of this machine. */
class PortProbeTest {
    static final Duration STEP = Duration.ofSeconds(3);

    @Test
    void aClosedPortIsNothing() throws Exception {
        assertThat(PortProbe.identify("localhost", FreePorts.one(), STEP)).isEqualTo(PortProbe.Finding.NOTHING);
    }

    @Test
    void anRmiRegistryAnswersJrmp() throws Exception {
        int port = FreePorts.one();
        Registry r = LocateRegistry.createRegistry(port);
        try {
            assertThat(PortProbe.identify("localhost", port, STEP)).isEqualTo(PortProbe.Finding.RMI_REGISTRY);
        } finally {
            UnicastRemoteObject.unexportObject(r, true);
        }
    }

    @Test
    void aWebServerAnswersHttp() throws Exception {
        HttpServer http = HttpServer.create(new InetSocketAddress("127.0.0.1", 0), 4);
        http.createContext("/", x -> {
            x.sendResponseHeaders(200, -1);
            x.close();
        });
        http.start();
        try {
            assertThat(PortProbe.identify("127.0.0.1", http.getAddress().getPort(), STEP)).isEqualTo(PortProbe.Finding.HTTP);
        } finally {
            http.stop(0);
        }
    }

    @Test
    void somethingThatOnlyHangsUpIsSilent() throws Exception {
        try (ServerSocket s = new ServerSocket(0)) {
            Thread t = new Thread(() -> {
                while (!s.isClosed()) {
                    try (Socket c = s.accept()) {
                        c.getInputStream().read();
                    } catch (Exception e) {
                        return;
                    }
                }
            });
            t.setDaemon(true);
            t.start();
            assertThat(PortProbe.identify("localhost", s.getLocalPort(), Duration.ofMillis(500))).isEqualTo(PortProbe.Finding.SILENT);
        }
    }

    /** A plain client port as the server runs it: it answers only a greeting of its own version. */
    @Test
    void aClientPortThatChecksTheVersionAnswersTheProbe() throws Exception {
        try (ServerSocket s = new ServerSocket(0)) {
            Thread t = new Thread(() -> {
                while (!s.isClosed()) {
                    try (Socket c = s.accept()) {
                        FrameCodec.readGreeting(new DataInputStream(c.getInputStream()));
                        FrameCodec.writeGreeting(new DataOutputStream(c.getOutputStream()));
                        c.getInputStream().read();
                    } catch (Exception e) {
                        // a probe of another kind, or a greeting of another version: hang up, as the server does
                    }
                }
            });
            t.setDaemon(true);
            t.start();
            assertThat(PortProbe.identify("localhost", s.getLocalPort(), Duration.ofMillis(500)))
                    .isEqualTo(PortProbe.Finding.RIPV_CLIENT_PORT_PLAIN);
        }
    }
}
