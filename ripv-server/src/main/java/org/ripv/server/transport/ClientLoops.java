package org.ripv.server.transport;

import java.io.IOException;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLEngine;

/**
 * The server's selector threads: a fixed few, whatever the number of clients. Each new
 * connection goes to the next one in turn and stays with it.
 */
public final class ClientLoops implements AutoCloseable {
    /** Reading and TLS are short and CPU-bound: about the cores, at least two, at most eight. */
    static final int LOOPS = Math.max(2, Math.min(8, Runtime.getRuntime().availableProcessors()));

    private final List<ClientLoop> loops = new ArrayList<>();
    private final AtomicInteger next = new AtomicInteger();

    public ClientLoops() throws IOException {
        try {
            for (int i = 0; i < LOOPS; i++) {
                loops.add(new ClientLoop("ripv-client-io-" + (i + 1)));
            }
        } catch (IOException e) {
            close();
            throw e;
        }
    }

    /**
     * A connection on one of the loops, not yet reading ({@link Connection#start}).
     *
     * @param tls the TLS context, or null for plain TCP
     */
    public Connection connection(SocketChannel channel, SSLContext tls) throws IOException {
        ClientLoop loop = loops.get(Math.floorMod(next.getAndIncrement(), loops.size()));
        SSLEngine engine = null;
        if (tls != null) {
            engine = tls.createSSLEngine();
            engine.setUseClientMode(false);
        }
        return new Connection(channel, engine, loop);
    }

    @Override
    public void close() {
        loops.forEach(ClientLoop::close);
    }
}
