package org.ripv.server.handlers;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.net.InetAddress;
import java.net.SocketException;
import java.nio.ByteBuffer;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import javax.net.ssl.SSLException;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.server.transport.Connection;
import org.ripv.wire.FrameCodec;
import org.ripv.wire.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One connected client (thesis: SocketHandler): parses the frames of its connection and hands each
 * request to the server. It is not a thread: the server's few selector threads
 * (org.ripv.server.transport) give it the bytes as they arrive, and it keeps only the part of a
 * frame still on its way. Replies and console pushes wait in this client's own
 * {@link ReplyWriter} queue, which the server's few {@link WriterPool} threads write. An idle
 * client thus costs no thread (docs/performance.md). A client that stops reading fills only its own
 * queue — and is then disconnected — while everyone else is served. Anything that breaks the
 * protocol closes this connection and nothing else.
 *
 * <p>A web console page is a client of the same kind made with {@link #inProcess}: no socket, reader
 * or writer, its requests handed in through {@link #received(IncomingServerMessage)} and its
 * messages given to its {@link Peer}; everything the server does with a client applies to it unchanged.
 *
 * <p>Longer than 400 lines because it is the one owner of a connection's state (logged in or not,
 * its pages, its pushes, its queue's bound): the rules that change that state read best beside it.
 */
public final class SocketHandler implements Connection.Receiver {
    private static final Logger log = LoggerFactory.getLogger(SocketHandler.class);
    /** Replies queued for a client that is not reading before it is cut off. */
    static final int MAX_QUEUED_REPLIES = 20_000;
    /** How long a peer may take to send its greeting, or the rest of a frame it began. */
    static final int READ_TIMEOUT_MILLIS = 30_000;
    private static final int GREETING = FrameCodec.MAGIC.length + Integer.BYTES;

    /**
     * Where an in-process client's messages go instead of a socket: a web console page
     * (org.ripv.server.web), which writes them with its own asynchronous sends. Never blocks.
     */
    public interface Peer {
        /** Queues a reply; false when the peer is too far behind (it is then disconnected). */
        boolean send(OutgoingServerMessage reply);

        /** Queues a push; {@code written} runs once it went out. False when busy or closed (see {@link #push}). */
        boolean push(OutgoingServerMessage message, Runnable written);

        /** The server ends this client: the peer closes its side (after what it has queued, if it can). */
        void close();

        /** The peer's address, the key of per-address limits. */
        InetAddress address();
    }

    /** What the server does with a client's requests. */
    public interface Dispatcher {
        /** On a selector thread: must not wait (a log-in holds the reading and waits elsewhere). */
        void received(SocketHandler client, IncomingServerMessage request);

        void closed(SocketHandler client);
    }

    private final Connection connection;
    private final String clientId;
    private final FrameCodec codec;
    private final Dispatcher dispatcher;
    private final ReplyWriter writer;
    private final ScheduledExecutorService timers;
    /** Not null for an in-process client, which has no connection or writer of its own. */
    private final Peer peer;
    private volatile IdBadge badge;
    private volatile List<String> roles = List.of();
    private volatile boolean closed;
    private volatile String closedWhy;

    // The frame being read; touched on the connection's selector thread only.
    private boolean greeted;
    /** The greeting, the four length bytes, or the body being gathered. */
    private byte[] part = new byte[GREETING];
    private int have;
    private boolean inBody;
    /** Bytes that came after a request while reading is held (a log-in being checked). */
    private byte[] held;
    private boolean holding;
    private ScheduledFuture<?> timeout;
    private long lastRead = System.nanoTime();

    /**
     * @param writers the server's writer threads, shared by all clients
     * @param timers  where the read deadline waits (only while a greeting or frame is half read)
     */
    public SocketHandler(Connection connection, String clientId, FrameCodec codec, WriterPool writers, Dispatcher dispatcher,
                         ScheduledExecutorService timers) {
        this.connection = connection;
        this.clientId = clientId;
        this.codec = codec;
        this.dispatcher = dispatcher;
        this.timers = timers;
        this.badge = new IdBadge(clientId, "");
        this.writer = new ReplyWriter(clientId, codec, MAX_QUEUED_REPLIES, writers, this::close);
        this.peer = null;
    }

    private SocketHandler(String clientId, Peer peer, Dispatcher dispatcher) {
        this.connection = null;
        this.clientId = clientId;
        this.codec = null;
        this.dispatcher = dispatcher;
        this.timers = null;
        this.badge = new IdBadge(clientId, "");
        this.writer = null;
        this.peer = peer;
    }

    /**
     * A client inside the server process (a web console page): no socket and no thread of its own;
     * its requests come in through {@link #received(IncomingServerMessage)} and its messages go to
     * {@code peer}. From the Post Office's side it is a client like any other.
     */
    public static SocketHandler inProcess(String clientId, Peer peer, Dispatcher dispatcher) {
        return new SocketHandler(clientId, Objects.requireNonNull(peer, "peer"), dispatcher);
    }

    /** Starts reading (the TLS handshake first); the greeting must come within the read timeout. */
    public void start() {
        if (connection != null) {
            connection.onLoop(this::armTimeout);
            connection.start(this, writer::drained);
        }
    }

    /**
     * A request from an in-process client, handed to the server exactly as a socket client's
     * (the caller's thread runs the dispatch, as a selector thread does).
     */
    public void received(IncomingServerMessage request) {
        if (peer == null) {
            throw new IllegalStateException("client " + clientId + " reads its requests from its socket");
        }
        if (closed) {
            return;
        }
        try {
            dispatcher.received(this, request);
        } catch (RuntimeException e) {
            log.error("client {}: unexpected failure", clientId, e);
            close();
        }
    }

    public String clientId() {
        return clientId;
    }

    /** The client id and the logged-in user (empty before log-in). */
    public IdBadge badge() {
        return badge;
    }

    public List<String> roles() {
        return roles;
    }

    private int failedLogins;

    /** Counts a failed log-in; returns how many this connection has had. */
    public synchronized int failedLogin() {
        return ++failedLogins;
    }

    public boolean isLoggedIn() {
        return !badge.user().isEmpty();
    }

    /** Marks the connection as logged in. */
    public void loggedIn(String user, List<String> userRoles) {
        this.badge = new IdBadge(clientId, user);
        this.roles = List.copyOf(userRoles);
    }

    public String remoteAddress() {
        if (peer != null) {
            return peer.address().getHostAddress() + " (web)";
        }
        return String.valueOf(connection.remoteAddress());
    }

    /** The peer's IP address, the key of per-address limits. */
    public InetAddress remoteInetAddress() {
        return peer != null ? peer.address() : connection.remoteInetAddress();
    }

    /**
     * Takes no further request from this client until {@link #resumeReading()}: a request that
     * waits elsewhere (a log-in's password check) is answered before the next is read, as when
     * each client had a reader thread of its own. Call from {@link Dispatcher#received}.
     */
    public void holdReading() {
        if (connection == null) {
            return; // an in-process client: its page waits for each answer itself
        }
        holding = true;
        connection.pauseReading();
    }

    /** Reads again after {@link #holdReading()}: first what arrived meanwhile. Any thread. */
    public void resumeReading() {
        if (connection == null) {
            return;
        }
        connection.onLoop(() -> {
            if (closed || !holding) {
                return;
            }
            holding = false;
            byte[] rest = held;
            held = null;
            if (rest != null) {
                received(ByteBuffer.wrap(rest));
            }
            if (!holding && !closed) {
                connection.resumeReading();
            }
        });
    }

    /** Sends this last reply, then closes: the client reads why it was cut off. */
    public void sendAndClose(OutgoingServerMessage last) {
        if (peer != null) {
            if (!closed) {
                peer.send(last);
            }
            close();
            return;
        }
        if (closed || !writer.offerLast(last)) {
            close();
        }
    }

    /** Queues a reply for this client; a client too far behind is disconnected. */
    public void send(OutgoingServerMessage reply) {
        if (closed) {
            return;
        }
        if (peer != null ? !peer.send(reply) : !writer.offer(reply)) {
            log.warn("client {} ({}) is not reading its replies; disconnecting it", clientId, remoteAddress());
            close();
        }
    }

    /**
     * Queues an unasked message (a console push); {@code written} runs on the writer thread once it
     * has been written and flushed, so a sender can keep one push in flight and hold the rest
     * itself. {@code frame}, when not null, is the message already encoded (once for every
     * client it goes to). Never blocks; false when the connection is closed or too far behind.
     */
    public boolean push(OutgoingServerMessage message, byte[] frame, Runnable written) {
        return !closed && (peer != null ? peer.push(message, written) : writer.push(message, frame, written));
    }

    /** As above, with the encoded frame asked for only when this client writes frames (not a web page's). */
    public boolean push(OutgoingServerMessage message, Supplier<byte[]> frame, Runnable written) {
        return !closed && (peer != null ? peer.push(message, written) : writer.push(message, frame.get(), written));
    }

    /** Bytes from the client, on its selector thread: whole frames go to the dispatcher. */
    @Override
    public void received(ByteBuffer bytes) {
        try {
            while (bytes.hasRemaining() && !closed) {
                if (holding) {
                    keep(bytes);
                    return;
                }
                int n = Math.min(bytes.remaining(), part.length - have);
                bytes.get(part, have, n);
                have += n;
                if (have == part.length) {
                    completed();
                }
            }
            lastRead = System.nanoTime();
            if (!greeted || inBody) {
                armTimeout();
            } else {
                cancelTimeout();
            }
        } catch (ProtocolException e) {
            ended("broke the protocol: " + e.getMessage(), e);
        } catch (IOException e) {
            ended("failed: " + e, e);
        } catch (RuntimeException e) {
            log.error("client {}: unexpected failure", clientId, e);
            ended("failed in the server: " + e, e);
        }
    }

    private void keep(ByteBuffer bytes) {
        int old = held == null ? 0 : held.length;
        byte[] more = new byte[old + bytes.remaining()];
        if (held != null) {
            System.arraycopy(held, 0, more, 0, old);
        }
        bytes.get(more, old, bytes.remaining());
        held = more;
    }

    /** The greeting, a length or a body is complete. */
    private void completed() throws IOException {
        if (!greeted) {
            FrameCodec.readGreeting(new DataInputStream(new ByteArrayInputStream(part)));
            greeted = true;
            DataOutputStream out = new DataOutputStream(connection.output());
            FrameCodec.writeGreeting(out);
            writer.open(connection.output(), connection::backedUp);
            expectLength();
        } else if (!inBody) {
            int length = ((part[0] & 0xff) << 24) | ((part[1] & 0xff) << 16) | ((part[2] & 0xff) << 8) | (part[3] & 0xff);
            if (length <= 0 || length > codec.maxFrame()) {
                throw new ProtocolException("frame length " + length + " outside 1.." + codec.maxFrame());
            }
            part = new byte[length];
            have = 0;
            inBody = true;
        } else {
            byte[] body = part;
            expectLength();
            Message m = codec.decode(body);
            if (!(m instanceof IncomingServerMessage request)) {
                throw new ProtocolException("a client may send only requests, not a " + m.getClass().getSimpleName());
            }
            dispatcher.received(this, request);
        }
    }

    private void expectLength() {
        part = new byte[Integer.BYTES];
        have = 0;
        inBody = false;
    }

    /**
     * While a greeting or a frame's body is half read: the rest must come within the read timeout
     * (a connection waiting between frames may wait as long as it likes; the gate's log-in deadline
     * bounds one that never logs in).
     */
    private void armTimeout() {
        if (timeout == null && !closed) {
            timeout = timers.schedule(() -> connection.onLoop(this::checkTimeout), READ_TIMEOUT_MILLIS, TimeUnit.MILLISECONDS);
        }
    }

    /** As a socket read timeout: {@link #READ_TIMEOUT_MILLIS} without a byte while a frame is half read ends it. */
    private void checkTimeout() {
        timeout = null;
        if (closed || (greeted && !inBody)) {
            return;
        }
        long quiet = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - lastRead);
        if (quiet < READ_TIMEOUT_MILLIS) {
            timeout = timers.schedule(() -> connection.onLoop(this::checkTimeout), READ_TIMEOUT_MILLIS - quiet, TimeUnit.MILLISECONDS);
            return;
        }
        ended(greeted ? "sent part of a frame and then nothing for " + READ_TIMEOUT_MILLIS / 1000 + " s"
                : "sent no greeting within " + READ_TIMEOUT_MILLIS / 1000 + " s", null);
    }

    private void cancelTimeout() {
        if (timeout != null) {
            timeout.cancel(false);
            timeout = null;
        }
    }

    /** The connection ended (the peer, TLS, the socket, a broken frame): logged, then closed. */
    @Override
    public void ended(String why, Exception cause) {
        if (closed) {
            return;
        }
        if (cause instanceof EOFException) {
            why = "disconnected";
        } else if (cause instanceof SocketException || cause instanceof SSLException) {
            why = why.startsWith("broke") ? why : "lost its connection: " + cause.getMessage();
        }
        if (why.startsWith("broke the protocol")) {
            log.warn("client {} ({}) {}", clientId, remoteAddress(), why);
        }
        closedWhy = why;
        close();
    }

    /** Closes the connection; the server forgets the client. Idempotent. */
    public void close() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
        }
        if (peer != null) {
            peer.close();
            dispatcher.closed(this);
            return;
        }
        String why = closedWhy == null ? "was disconnected" : closedWhy;
        log.info("client {} ({}{}) {}", clientId, remoteAddress(), isLoggedIn() ? ", " + badge.user() : "", why);
        writer.stop();
        connection.close();
        connection.onLoop(this::cancelTimeout);
        dispatcher.closed(this);
    }

    public boolean isClosed() {
        return closed;
    }
}
