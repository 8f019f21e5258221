package org.ripv.server.handlers;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import java.net.SocketException;
import java.util.List;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.wire.FrameCodec;
import org.ripv.wire.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One connected client (thesis: SocketHandler). A reader thread reads frames and hands each
 * request to the server; replies and console pushes wait in this client's own {@link ReplyWriter}
 * queue, which the server's few {@link WriterPool} threads write (an idle client costs one
 * thread, its reader; docs/performance.md). A client that stops reading fills only its own
 * queue — and is then disconnected — while everyone else is served. Anything that breaks the protocol closes this connection and nothing else.
 *
 * <p>A web console page is a client of the same kind made with {@link #inProcess}: no socket, reader
 * or writer, its requests handed in through {@link #received} and its messages given to its
 * {@link Peer}; everything the server does with a client applies to it unchanged.
 */
public final class SocketHandler {
    private static final Logger log = LoggerFactory.getLogger(SocketHandler.class);
    /** Replies queued for a client that is not reading before it is cut off. */
    static final int MAX_QUEUED_REPLIES = 20_000;
    /** How long a peer may take to send its greeting, or the rest of a frame it began. */
    static final int READ_TIMEOUT_MILLIS = 30_000;
    /** Stream buffers: small, since every idle client keeps two; large frames bypass them anyway. */
    static final int BUFFER = 8 * 1024;

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
        java.net.InetAddress address();
    }

    /** What the server does with a client's requests. */
    public interface Dispatcher {
        void received(SocketHandler client, IncomingServerMessage request);

        void closed(SocketHandler client);
    }

    private final Socket socket;
    private final String clientId;
    private final FrameCodec codec;
    private final Dispatcher dispatcher;
    private final ReplyWriter writer;
    private final Thread reader;
    /** Not null for an in-process client, which has no socket, reader or writer of its own. */
    private final Peer peer;
    private volatile IdBadge badge;
    private volatile List<String> roles = List.of();
    private volatile boolean closed;

    /** @param writers the server's writer threads, shared by all clients */
    public SocketHandler(Socket socket, String clientId, FrameCodec codec, WriterPool writers, Dispatcher dispatcher) {
        this.socket = socket;
        this.clientId = clientId;
        this.codec = codec;
        this.dispatcher = dispatcher;
        this.badge = new IdBadge(clientId, "");
        this.writer = new ReplyWriter(clientId, codec, MAX_QUEUED_REPLIES, writers, this::close);
        this.reader = new Thread(this::readLoop, "ripv-socket-handler-" + clientId);
        reader.setDaemon(true);
        this.peer = null;
    }

    private SocketHandler(String clientId, Peer peer, Dispatcher dispatcher) {
        this.socket = null;
        this.clientId = clientId;
        this.codec = null;
        this.dispatcher = dispatcher;
        this.badge = new IdBadge(clientId, "");
        this.writer = null;
        this.reader = null;
        this.peer = peer;
    }

    /**
     * A client inside the server process (a web console page): no socket and no thread of its own;
     * its requests come in through {@link #received} and its messages go to {@code peer}. From
     * the Post Office's side it is a client like any other.
     */
    public static SocketHandler inProcess(String clientId, Peer peer, Dispatcher dispatcher) {
        return new SocketHandler(clientId, java.util.Objects.requireNonNull(peer, "peer"), dispatcher);
    }

    public void start() {
        if (reader != null) {
            reader.start();
        }
    }

    /**
     * A request from an in-process client, handed to the server exactly as the reader hands a
     * socket client's (the caller's thread runs the dispatch, as a reader thread does).
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
        return String.valueOf(socket.getRemoteSocketAddress());
    }

    /** The peer's IP address, the key of per-address limits. */
    public java.net.InetAddress remoteInetAddress() {
        return peer != null ? peer.address() : socket.getInetAddress();
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

    private void readLoop() {
        String why = "closed the connection";
        try {
            socket.setTcpNoDelay(true);
            socket.setSoTimeout(READ_TIMEOUT_MILLIS);
            DataInputStream in = new DataInputStream(new BufferedInputStream(socket.getInputStream(), BUFFER));
            DataOutputStream greet = new DataOutputStream(socket.getOutputStream());
            FrameCodec.readGreeting(in);
            FrameCodec.writeGreeting(greet);
            writer.open(socket.getOutputStream(), BUFFER);
            while (!closed) {
                socket.setSoTimeout(0);
                int length = in.readInt();
                socket.setSoTimeout(READ_TIMEOUT_MILLIS);
                Message m = codec.readBody(in, length);
                if (!(m instanceof IncomingServerMessage request)) {
                    throw new ProtocolException("a client may send only requests, not a " + m.getClass().getSimpleName());
                }
                dispatcher.received(this, request);
            }
        } catch (EOFException e) {
            why = "disconnected";
        } catch (ProtocolException e) {
            why = "broke the protocol: " + e.getMessage();
            log.warn("client {} ({}) {}", clientId, remoteAddress(), why);
        } catch (SocketException e) {
            why = closed ? "was disconnected" : "lost its connection: " + e.getMessage();
        } catch (IOException e) {
            why = "failed: " + e;
        } catch (RuntimeException e) {
            why = "failed in the server: " + e;
            log.error("client {}: unexpected failure", clientId, e);
        } finally {
            log.info("client {} ({}{}) {}", clientId, remoteAddress(), isLoggedIn() ? ", " + badge.user() : "", why);
            close();
        }
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
        writer.stop();
        try {
            socket.close();
        } catch (IOException ignored) {
            // closing anyway
        }
        dispatcher.closed(this);
    }

    public boolean isClosed() {
        return closed;
    }
}
