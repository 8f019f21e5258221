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
 */
public final class SocketHandler {
    private static final Logger log = LoggerFactory.getLogger(SocketHandler.class);
    /** Replies queued for a client that is not reading before it is cut off. */
    static final int MAX_QUEUED_REPLIES = 20_000;
    /** How long a peer may take to send its greeting, or the rest of a frame it began. */
    static final int READ_TIMEOUT_MILLIS = 30_000;
    /** Stream buffers: small, since every idle client keeps two; large frames bypass them anyway. */
    static final int BUFFER = 8 * 1024;

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
    }

    public void start() {
        reader.start();
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
        return String.valueOf(socket.getRemoteSocketAddress());
    }

    /** The peer's IP address, the key of per-address limits. */
    public java.net.InetAddress remoteInetAddress() {
        return socket.getInetAddress();
    }

    /** Sends this last reply, then closes: the client reads why it was cut off. */
    public void sendAndClose(OutgoingServerMessage last) {
        if (closed || !writer.offerLast(last)) {
            close();
        }
    }

    /** Queues a reply for this client; a client too far behind is disconnected. */
    public void send(OutgoingServerMessage reply) {
        if (closed) {
            return;
        }
        if (!writer.offer(reply)) {
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
        return !closed && writer.push(message, frame, written);
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
