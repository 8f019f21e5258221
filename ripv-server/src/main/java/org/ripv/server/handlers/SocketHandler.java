package org.ripv.server.handlers;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import java.net.SocketException;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
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
 * request to the server; a writer thread drains this client's own reply queue, so a client that
 * stops reading fills only its own queue — and is then disconnected — while everyone else is
 * served. Anything that breaks the protocol closes this connection and nothing else.
 */
public final class SocketHandler {
    private static final Logger log = LoggerFactory.getLogger(SocketHandler.class);
    /** Replies queued for a client that is not reading before it is cut off. */
    static final int MAX_QUEUED_REPLIES = 20_000;
    /** How long a peer may take to send its greeting, or the rest of a frame it began. */
    static final int READ_TIMEOUT_MILLIS = 30_000;

    /** What the server does with a client's requests. */
    public interface Dispatcher {
        void received(SocketHandler client, IncomingServerMessage request);

        void closed(SocketHandler client);
    }

    private static final OutgoingServerMessage POISON = new OutgoingServerMessage(
            org.ripv.messages.Header.request(0, "", "", null), org.ripv.messages.Footer.unanswered());

    private final Socket socket;
    private final String clientId;
    private final FrameCodec codec;
    private final Dispatcher dispatcher;
    private final BlockingQueue<OutgoingServerMessage> replies = new ArrayBlockingQueue<>(MAX_QUEUED_REPLIES);
    /** A push: its frame if encoded once for many clients (else null), and what to run once it went out. */
    private record Push(byte[] frame, Runnable written) {}

    /** Pushes whose sender wants to hear when they went out (console watchers pace themselves by it). */
    private final java.util.Map<OutgoingServerMessage, Push> afterWrite = new java.util.concurrent.ConcurrentHashMap<>();
    private final Thread reader;
    private final Thread writer;
    private volatile IdBadge badge;
    private volatile List<String> roles = List.of();
    private volatile boolean closed;

    public SocketHandler(Socket socket, String clientId, FrameCodec codec, Dispatcher dispatcher) {
        this.socket = socket;
        this.clientId = clientId;
        this.codec = codec;
        this.dispatcher = dispatcher;
        this.badge = new IdBadge(clientId, "");
        this.reader = new Thread(this::readLoop, "ripv-socket-handler-" + clientId);
        this.writer = new Thread(this::writeLoop, "ripv-socket-writer-" + clientId);
        reader.setDaemon(true);
        writer.setDaemon(true);
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

    /** Queues a reply for this client; a client too far behind is disconnected. */
    public void send(OutgoingServerMessage reply) {
        if (closed) {
            return;
        }
        if (!replies.offer(reply)) {
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
        if (closed || replies.remainingCapacity() < MAX_QUEUED_REPLIES / 2) {
            return false;
        }
        afterWrite.put(message, new Push(frame, written));
        if (!replies.offer(message)) {
            afterWrite.remove(message);
            return false;
        }
        return true;
    }

    private void readLoop() {
        String why = "closed the connection";
        try {
            socket.setTcpNoDelay(true);
            socket.setSoTimeout(READ_TIMEOUT_MILLIS);
            DataInputStream in = new DataInputStream(new BufferedInputStream(socket.getInputStream(), 64 * 1024));
            DataOutputStream greet = new DataOutputStream(socket.getOutputStream());
            FrameCodec.readGreeting(in);
            FrameCodec.writeGreeting(greet);
            writer.start();
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

    private void writeLoop() {
        List<Runnable> flushed = new java.util.ArrayList<>();
        try (DataOutputStream out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream(), 64 * 1024))) {
            while (!closed) {
                OutgoingServerMessage m = replies.take();
                if (m == POISON) {
                    break;
                }
                Push push = afterWrite.remove(m);
                if (push != null) {
                    flushed.add(push.written());
                }
                try {
                    if (push != null && push.frame() != null) {
                        out.writeInt(push.frame().length);
                        out.write(push.frame());
                    } else {
                        codec.writeNoFlush(out, m);
                    }
                } catch (ProtocolException tooLarge) {
                    // Nothing was written yet: tell the client instead of cutting it off. A progress
                    // report is only dropped, so the request still ends in its one real final reply.
                    log.warn("client {}: reply to #{} not sent: {}", clientId, m.header().messageId(), tooLarge.getMessage());
                    if (m.status().isFinal()) {
                        codec.writeNoFlush(out, new OutgoingServerMessage(m.header(), org.ripv.messages.Footer.error(
                                m.footer().serviceId(), org.ripv.messages.ErrorCode.TOO_LARGE,
                                "the reply was too large to send (" + tooLarge.getMessage() + "); ask for less, e.g. fewer rows")
                                .via("RIPVServer")));
                    }
                }
                if (replies.isEmpty()) {
                    out.flush();
                    flushed.forEach(Runnable::run);
                    flushed.clear();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            log.debug("client {}: write failed: {}", clientId, e.toString());
        } finally {
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
        replies.clear();
        afterWrite.clear();
        replies.offer(POISON);
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
