package org.ripv.it;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.rmi.server.RMIServerSocketFactory;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * A service's RMI port behind a relay that can go dark, the way a host behind a firewall looks
 * from the server: frozen, it holds every byte of the connections already open in both
 * directions (as a path that drops packets does) and refuses new connections (as a firewall
 * that rejects them does; the multi-host test covers connects that hang). Export the service on
 * {@link #port()} with this as its server socket factory: the stub then names the relay, and the
 * relay feeds the real port.
 */
final class BlackHoleRelay implements RMIServerSocketFactory, AutoCloseable {
    private static final InetAddress LOOPBACK = InetAddress.getLoopbackAddress();
    private final int port;
    private volatile ServerSocket front;
    private final Object gate = new Object();
    private final List<Socket> sockets = new CopyOnWriteArrayList<>();
    private volatile boolean frozen;
    private volatile boolean closed;
    private volatile int backPort;

    BlackHoleRelay() throws IOException {
        front = listen(0);
        port = front.getLocalPort();
        Thread t = new Thread(this::acceptLoop, "black-hole-relay");
        t.setDaemon(true);
        t.start();
    }

    /** The port the service's stub names. */
    int port() {
        return port;
    }

    private static ServerSocket listen(int port) throws IOException {
        ServerSocket s = new ServerSocket();
        s.setReuseAddress(true);
        s.bind(new java.net.InetSocketAddress(LOOPBACK, port), 50);
        return s;
    }

    void freeze() throws IOException {
        frozen = true;
        front.close();
    }

    void thaw() throws IOException {
        synchronized (gate) {
            if (frozen && !closed) {
                front = listen(port);
            }
            frozen = false;
            gate.notifyAll();
        }
    }

    @Override
    public ServerSocket createServerSocket(int port) throws IOException {
        ServerSocket back = new ServerSocket(0, 50, LOOPBACK);
        backPort = back.getLocalPort();
        return back;
    }

    private void waitWhileFrozen() throws InterruptedException {
        synchronized (gate) {
            while (frozen && !closed) {
                gate.wait(200);
            }
        }
    }

    private void acceptLoop() {
        while (!closed) {
            try {
                waitWhileFrozen();
                Socket c = front.accept();
                sockets.add(c);
                Socket b = new Socket(LOOPBACK, backPort);
                sockets.add(b);
                pump(c, b);
                pump(b, c);
            } catch (IOException | InterruptedException e) {
                if (closed) {
                    return;
                }
            }
        }
    }

    private void pump(Socket from, Socket to) {
        Thread t = new Thread(() -> {
            byte[] buf = new byte[8192];
            try (InputStream in = from.getInputStream(); OutputStream out = to.getOutputStream()) {
                int n;
                while ((n = in.read(buf)) >= 0) {
                    waitWhileFrozen(); // bytes held, as on a link that drops them
                    out.write(buf, 0, n);
                    out.flush();
                }
            } catch (IOException | InterruptedException e) {
                // one side closed
            } finally {
                close(from);
                close(to);
            }
        }, "black-hole-pump");
        t.setDaemon(true);
        t.start();
    }

    private static void close(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }

    @Override
    public void close() throws IOException {
        closed = true;
        synchronized (gate) {
            gate.notifyAll();
        }
        front.close();
        sockets.forEach(BlackHoleRelay::close);
    }

    @Override
    public boolean equals(Object o) {
        return o == this;
    }

    @Override
    public int hashCode() {
        return System.identityHashCode(this);
    }
}
