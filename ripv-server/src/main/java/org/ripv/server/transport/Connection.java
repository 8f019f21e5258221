package org.ripv.server.transport;

import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.SelectionKey;
import java.nio.channels.SocketChannel;
import java.util.ArrayDeque;
import javax.net.ssl.SSLEngine;
import javax.net.ssl.SSLEngineResult;
import javax.net.ssl.SSLException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One client's non-blocking socket, with TLS through an {@link SSLEngine} or plain. Its loop reads
 * it and hands the plain bytes to its {@link Receiver}; any thread may write through
 * {@link #output()}, which sends what the socket takes at once and keeps the rest until the loop
 * finds the socket writable. Idle, it holds no buffer: reads go through its loop's buffers, and
 * what waits to be sent is held only while it waits.
 *
 * <p>Longer than 400 lines because the TLS engine's states (handshake, wrap, unwrap, close) and
 * the socket's readiness are one state machine: split, each half would reach into the other's
 * buffers.
 */
public final class Connection {
    private static final Logger log = LoggerFactory.getLogger(Connection.class);
    /**
     * Bytes waiting for a peer that does not read, beyond which {@link #backedUp()} is true and the
     * reply writer leaves the rest in the client's bounded reply queue (issue 10's slow reader).
     */
    static final int HIGH_WATER = 256 * 1024;
    /** What the output gathers before it is sent (a few small frames become one TLS record). */
    static final int GATHER = 8 * 1024;
    private static final ByteBuffer EMPTY = ByteBuffer.allocate(0);
    /** The writers' buffer for TLS records, one per thread, not one per connection. */
    private static final ThreadLocal<ByteBuffer> NET_OUT = ThreadLocal.withInitial(() -> ByteBuffer.allocate(GATHER * 4));

    /** Who is told what arrives: called on the loop's thread only. */
    public interface Receiver {
        /** Plain bytes from the peer; what is not taken now is lost (keep it). */
        void received(ByteBuffer bytes) throws IOException;

        /** The peer closed, broke TLS, or the socket failed: {@code why} for the log. */
        void ended(String why, Exception cause);
    }

    private final SocketChannel channel;
    private final SSLEngine engine;
    private final ClientLoop loop;
    private final InetSocketAddress remote;
    private final Output output = new Output();
    private final Object sending = new Object();
    /** Records (or plain bytes) the socket did not take yet; guarded by {@link #sending}. */
    private final ArrayDeque<ByteBuffer> waiting = new ArrayDeque<>(2);
    private volatile int waitingBytes;
    private boolean wasBackedUp;
    private Runnable drained = () -> {};
    private Receiver receiver;
    private SelectionKey key;
    /** The start of a TLS record a read cut off; null almost always. */
    private byte[] partialRecord;
    private volatile boolean closed;
    private boolean readPaused;

    Connection(SocketChannel channel, SSLEngine engine, ClientLoop loop) throws IOException {
        this.channel = channel;
        this.engine = engine;
        this.loop = loop;
        this.remote = (InetSocketAddress) channel.getRemoteAddress();
        channel.configureBlocking(false);
        channel.setOption(StandardSocketOptions.TCP_NODELAY, true);
    }

    /** Registers with the loop and starts reading (and the TLS handshake). */
    public void start(Receiver r, Runnable whenDrained) {
        this.receiver = r;
        this.drained = whenDrained;
        loop.execute(() -> {
            if (closed) {
                return;
            }
            try {
                key = channel.register(loop.selector(), readPaused ? 0 : SelectionKey.OP_READ, this);
                if (engine != null) {
                    engine.beginHandshake();
                    handshake();
                }
            } catch (IOException | RuntimeException e) {
                end("failed to start: " + e, e);
            }
        });
    }

    public SocketAddress remoteAddress() {
        return remote;
    }

    public InetAddress remoteInetAddress() {
        return remote.getAddress();
    }

    /** Where replies are written; {@code flush()} sends them. Thread-safe as a whole frame per writer at a time. */
    public OutputStream output() {
        return output;
    }

    /** True while more than {@link #HIGH_WATER} bytes wait for the peer to read. */
    public boolean backedUp() {
        return waitingBytes > HIGH_WATER;
    }

    /** Stops reading (no more requests are taken until {@link #resumeReading}); on the loop's thread. */
    public void pauseReading() {
        readPaused = true;
        setInterest();
    }

    /** Reads again; on the loop's thread ({@link #onLoop}). */
    public void resumeReading() {
        readPaused = false;
        setInterest();
    }

    /** Runs {@code task} on this connection's loop thread. */
    public void onLoop(Runnable task) {
        loop.execute(task);
    }

    /** Called by the loop when the socket has bytes. */
    void readable() {
        try {
            ByteBuffer net = loop.netIn;
            net.clear();
            if (partialRecord != null) {
                net.put(partialRecord);
                partialRecord = null;
            }
            int n = channel.read(net);
            net.flip();
            if (engine == null) {
                if (n < 0) {
                    end("disconnected", new EOFException());
                    return;
                }
                receiver.received(net);
                return;
            }
            unwrap(net);
            if (net.hasRemaining() && !closed) {
                partialRecord = new byte[net.remaining()];
                net.get(partialRecord);
            }
            if (n < 0 && !closed) {
                end("disconnected", new EOFException());
            }
        } catch (SSLException e) {
            end("broke TLS: " + e.getMessage(), e);
        } catch (IOException e) {
            end(closed ? "was disconnected" : "lost its connection: " + e.getMessage(), e);
        } catch (RuntimeException e) {
            log.error("client connection {}: unexpected failure", remote, e);
            end("failed in the server: " + e, e);
        }
    }

    private void unwrap(ByteBuffer net) throws IOException {
        while (net.hasRemaining() && !closed) {
            ByteBuffer app = loop.appIn;
            app.clear();
            SSLEngineResult r = engine.unwrap(net, app);
            switch (r.getStatus()) {
                case BUFFER_OVERFLOW -> {
                    loop.appIn = ByteBuffer.allocate(Math.max(app.capacity() * 2, engine.getSession().getApplicationBufferSize()));
                    continue;
                }
                case BUFFER_UNDERFLOW -> {
                    return; // the rest of the record is still on its way
                }
                case CLOSED -> {
                    end("disconnected", new EOFException());
                    return;
                }
                case OK -> { }
            }
            handshake();
            app.flip();
            if (app.hasRemaining()) {
                receiver.received(app);
            } else if (r.bytesConsumed() == 0) {
                return; // the engine wants more than is here
            }
        }
    }

    /** Does what the handshake (or a post-handshake message) asks: tasks here, records to send. */
    private void handshake() throws IOException {
        while (!closed) {
            switch (engine.getHandshakeStatus()) {
                case NEED_TASK -> {
                    for (Runnable t = engine.getDelegatedTask(); t != null; t = engine.getDelegatedTask()) {
                        t.run(); // a signature or key agreement: about a millisecond, once per connection
                    }
                }
                case NEED_WRAP -> {
                    synchronized (sending) {
                        wrapAndSend(EMPTY);
                    }
                }
                default -> {
                    return;
                }
            }
        }
    }

    /** Called by the loop when the socket takes bytes again. */
    void writable() {
        boolean nowDrained;
        try {
            synchronized (sending) {
                sendWaiting();
                nowDrained = waiting.isEmpty() && wasBackedUp;
                if (waiting.isEmpty()) {
                    wasBackedUp = false;
                }
            }
            setInterest();
        } catch (IOException e) {
            end("lost its connection: " + e.getMessage(), e);
            return;
        }
        if (nowDrained) {
            drained.run();
        }
    }

    private void sendWaiting() throws IOException {
        while (!waiting.isEmpty()) {
            ByteBuffer head = waiting.peek();
            channel.write(head);
            if (head.hasRemaining()) {
                return;
            }
            waiting.poll();
            waitingBytes -= head.capacity();
        }
    }

    /** Sends bytes (records, or plain bytes); what the socket does not take waits. Holds {@link #sending}. */
    private void send(ByteBuffer bytes) throws IOException {
        if (waiting.isEmpty()) {
            channel.write(bytes);
            if (!bytes.hasRemaining()) {
                return;
            }
        }
        ByteBuffer copy = ByteBuffer.allocate(bytes.remaining());
        copy.put(bytes).flip();
        waiting.add(copy);
        waitingBytes += copy.capacity();
        if (waitingBytes > HIGH_WATER) {
            wasBackedUp = true;
        }
        if (waiting.size() == 1) {
            loop.execute(this::setInterest);
        }
    }

    /** Encrypts and sends {@code app} (all of it). Holds {@link #sending}. */
    private void wrapAndSend(ByteBuffer app) throws IOException {
        if (engine == null) {
            send(app);
            return;
        }
        do {
            ByteBuffer net = NET_OUT.get();
            net.clear();
            SSLEngineResult r = engine.wrap(app, net);
            if (r.getStatus() == SSLEngineResult.Status.BUFFER_OVERFLOW) {
                NET_OUT.set(ByteBuffer.allocate(Math.max(net.capacity() * 2, engine.getSession().getPacketBufferSize())));
                continue;
            }
            net.flip();
            if (net.hasRemaining()) {
                send(net);
            }
            if (r.getStatus() == SSLEngineResult.Status.CLOSED) {
                if (app.hasRemaining()) {
                    throw new ClosedChannelException();
                }
                return; // the close_notify, or nothing after it
            }
            if (r.getHandshakeStatus() != SSLEngineResult.HandshakeStatus.NEED_WRAP && !app.hasRemaining()) {
                return;
            }
        } while (true);
    }

    /** Reading unless paused or closed; writing while bytes wait. On the loop's thread. */
    private void setInterest() {
        SelectionKey k = key;
        if (k == null || !k.isValid()) {
            return;
        }
        int ops = readPaused ? 0 : SelectionKey.OP_READ;
        if (waitingBytes > 0) {
            ops |= SelectionKey.OP_WRITE;
        }
        k.interestOps(ops);
    }

    private void end(String why, Exception cause) {
        if (closed) {
            return;
        }
        receiver.ended(why, cause);
        close();
    }

    /**
     * Closes: a TLS close_notify if the socket takes it at once (a peer that stopped reading gets
     * none), then the socket. Idempotent; any thread.
     */
    public void close() {
        synchronized (sending) {
            if (closed) {
                return;
            }
            closed = true;
            try {
                sendWaiting(); // a last reply ("disconnecting: ...") the socket takes at once still goes
            } catch (IOException ignored) {
                // the peer is gone
            }
            boolean stuck = !waiting.isEmpty(); // a record half sent: a close_notify after it would be garbage
            waiting.clear();
            waitingBytes = 0;
            if (engine != null && !stuck) {
                engine.closeOutbound();
                try {
                    wrapAndSend(EMPTY);
                } catch (IOException | RuntimeException ignored) {
                    // the peer may be gone already
                }
            }
        }
        try {
            channel.close();
        } catch (IOException ignored) {
            // closing anyway
        }
        loop.selector().wakeup(); // the selector releases the socket at its next select
    }

    public boolean isClosed() {
        return closed;
    }

    /**
     * What writers write: gathered in a buffer that exists only while bytes wait in it, and sent
     * (encrypted) at each flush or when full. One writer at a time (the reply writer's turn).
     */
    private final class Output extends OutputStream {
        private byte[] buf;
        private int count;

        @Override
        public void write(int b) throws IOException {
            if (buf == null) {
                buf = new byte[GATHER];
            } else if (count == buf.length) {
                flushBuffer();
                buf = new byte[GATHER];
            }
            buf[count++] = (byte) b;
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            if (len >= GATHER) {
                flushBuffer();
                sendNow(ByteBuffer.wrap(b, off, len));
                return;
            }
            if (buf == null) {
                buf = new byte[GATHER];
            } else if (count + len > buf.length) {
                flushBuffer();
                buf = new byte[GATHER];
            }
            System.arraycopy(b, off, buf, count, len);
            count += len;
        }

        @Override
        public void flush() throws IOException {
            flushBuffer();
        }

        private void flushBuffer() throws IOException {
            if (buf != null && count > 0) {
                sendNow(ByteBuffer.wrap(buf, 0, count));
            }
            buf = null;
            count = 0;
        }

        private void sendNow(ByteBuffer app) throws IOException {
            synchronized (sending) {
                if (closed) {
                    throw new ClosedChannelException();
                }
                wrapAndSend(app);
            }
        }
    }
}
