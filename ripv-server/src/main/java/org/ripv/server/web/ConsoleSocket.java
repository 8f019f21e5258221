package org.ripv.server.web;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.eclipse.jetty.websocket.api.Callback;
import org.eclipse.jetty.websocket.api.Session;
import org.eclipse.jetty.websocket.common.WebSocketSession;
import org.eclipse.jetty.websocket.core.Frame;
import org.eclipse.jetty.websocket.core.OpCode;
import org.ripv.messages.Header;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.server.handlers.SocketHandler;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One page's WebSocket ({@code /ws}): a Post Office client in the server's own process, with no
 * socket or thread of its own (docs/web.md). The page sends
 * {@code {"id":7,"mailbox":"…","body":"dir","priority":"normal","csrf":"…"}} (an upload chunk adds
 * {@code "file"} and {@code "data"}, see {@link FileChunks}); this hands it to its
 * {@link SocketHandler} as that client's request, so the server's own rules decide; every reply
 * and console push goes back as JSON ({@link WebReplies}) with Jetty's asynchronous send.
 *
 * <p>What waits for a page is bounded: at most {@link #MAX_PUSHES} pushes, {@link #MAX_PUSH_BYTES} bytes of them, not yet written (beyond
 * that the server's watcher holds the lines in its own bounded backlog and later tells the page
 * how many it skipped), and at most {@link WebConsole#MAX_QUEUED_FRAMES} frames in all, after
 * which the page is cut off. A page that stops reading thus costs its own few frames and slows
 * nobody. (Public only because Jetty calls its listener methods reflectively; nothing outside
 * this package makes one.)
 */
public final class ConsoleSocket implements Session.Listener.AutoDemanding, SocketHandler.Peer, AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(ConsoleSocket.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    /** Pushes queued on the socket and not yet written, beyond which a push is refused (the watcher keeps it). */
    static final int MAX_PUSHES = 64;
    /** Bytes of pushes queued for this page, beyond which no more are taken (one is always let through). */
    static final long MAX_PUSH_BYTES = 64 * 1024;

    private final WebSessions sessions;
    private final WebSessions.Session login;
    private final PostOfficeDoor door;
    private final PushJson json;
    private final InetAddress address;
    private final AtomicInteger queued = new AtomicInteger();
    private final AtomicLong pushBytes = new AtomicLong();
    private volatile Session socket;
    private volatile SocketHandler client;

    ConsoleSocket(WebSessions sessions, WebSessions.Session login, PostOfficeDoor door, PushJson json, InetAddress address) {
        this.sessions = sessions;
        this.login = login;
        this.door = door;
        this.json = json;
        this.address = address;
    }

    @Override
    public void onWebSocketOpen(Session session) {
        this.socket = session;
        login.sockets.add(this);
        try {
            client = door.open(this, login.user, login.roles);
        } catch (IOException e) {
            session.close(1013, truncate("the server takes no more clients: " + e.getMessage()), Callback.NOOP);
        }
    }

    @Override
    public void onWebSocketText(String text) {
        if (!sessions.live(login)) {
            refuse(1008, "the session has ended; log in again");
            return;
        }
        try {
            JsonNode m = JSON.readTree(text);
            if (!login.csrf(m.path("csrf").asText(null))) {
                refuse(1008, "no or a wrong CSRF token");
                return;
            }
            sessions.find(login.id); // the user acted: the session is not idle
            SocketHandler c = client;
            if (c != null) {
                Header h = Header.request(m.path("id").asLong(), m.path("mailbox").asText(""), m.path("body").asText(""),
                        Priority.parse(m.path("priority").asText("normal")));
                org.ripv.messages.Attachment chunk = FileChunks.attachment(m);
                c.received(new IncomingServerMessage(chunk == null ? h : h.withAttachment(chunk)));
            }
        } catch (IOException | IllegalArgumentException e) {
            sendText("{\"type\":\"error\",\"text\":" + quote("could not send: " + e.getMessage()) + "}", null);
        }
    }

    @Override
    public boolean send(OutgoingServerMessage reply) {
        return reply.header().messageId() == 0 ? sendShared(json.of(reply), null) : sendText(json.reply(reply), null);
    }

    /**
     * A push: refused while {@link #MAX_PUSHES} are queued, or while the pushes waiting add up to
     * {@link #MAX_PUSH_BYTES} (counted as if each were this page's alone, though a push every
     * watcher shares is in memory once); one is always let through, however large.
     */
    @Override
    public boolean push(OutgoingServerMessage message, Runnable written) {
        if (queued.get() >= MAX_PUSHES || queued.get() > 0 && pushBytes.get() >= MAX_PUSH_BYTES) {
            return false;
        }
        return sendShared(json.of(message), written);
    }

    @Override
    public InetAddress address() {
        return address;
    }

    /** Queues a frame of this page's own (a reply); false when closed or too much waits (the page is then cut off). */
    private boolean sendText(String text, Runnable written) {
        Session s = socket;
        if (s == null || !s.isOpen() || !admit()) {
            return false;
        }
        s.sendText(text, new Callback() {
            @Override
            public void succeed() {
                ConsoleSocket.this.written(0, written);
            }

            @Override
            public void fail(Throwable x) {
                failed(0, x);
            }
        });
        return true;
    }

    /**
     * Queues a text frame whose UTF-8 bytes may be shared with other pages ({@link PushJson}):
     * Jetty's core session (under the API's session Jetty gives us) sends a duplicate of the
     * buffer, so the bytes are not copied per page.
     */
    private boolean sendShared(ByteBuffer utf8, Runnable written) {
        Session s = socket;
        if (s == null || !s.isOpen() || !admit()) {
            return false;
        }
        int own = utf8.remaining();
        pushBytes.addAndGet(own);
        ((WebSocketSession) s).getCoreSession().sendFrame(new Frame(OpCode.TEXT, utf8.duplicate()), new org.eclipse.jetty.util.Callback() {
            @Override
            public void succeeded() {
                ConsoleSocket.this.written(own, written);
            }

            @Override
            public void failed(Throwable x) {
                ConsoleSocket.this.failed(own, x);
            }
        }, false);
        return true;
    }

    /** Counts one more frame waiting; false (and the page is cut off) past {@link WebConsole#MAX_QUEUED_FRAMES}. */
    private boolean admit() {
        if (queued.incrementAndGet() > WebConsole.MAX_QUEUED_FRAMES) {
            queued.decrementAndGet();
            log.info("web console socket of {} from {} is not reading; cutting it off", login.user, address.getHostAddress());
            close();
            return false;
        }
        return true;
    }

    private void written(int bytes, Runnable then) {
        pushBytes.addAndGet(-bytes);
        queued.decrementAndGet();
        if (then != null) {
            then.run();
        }
    }

    private void failed(int bytes, Throwable x) {
        pushBytes.addAndGet(-bytes);
        queued.decrementAndGet();
        // The socket broke or Jetty's own queue is full: cut it off.
        log.info("web console socket of {} closed: {}", login.user, x.toString());
        close();
    }

    @Override
    public void onWebSocketClose(int statusCode, String reason) {
        close();
    }

    @Override
    public void onWebSocketError(Throwable cause) {
        close();
    }

    private void refuse(int code, String reason) {
        Session s = socket;
        if (s != null && s.isOpen()) {
            s.close(code, reason, Callback.NOOP);
        }
        close();
    }

    /**
     * Ends the page's socket and its Post Office client (the server forgets its watches, pending
     * requests and locks as for any client). The server's own close of the client comes here too;
     * frames already queued go out before the close frame.
     */
    @Override
    public void close() {
        login.sockets.remove(this);
        SocketHandler c = client;
        if (c != null) {
            c.close(); // idempotent: when the server closed it, this returns at once
        }
        Session s = socket;
        if (s != null && s.isOpen()) {
            s.close(1000, "closed", Callback.NOOP);
        }
    }

    private static String quote(String s) {
        try {
            return JSON.writeValueAsString(s);
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            return "\"\"";
        }
    }

    private static String truncate(String s) {
        return s.length() > 100 ? s.substring(0, 100) : s;
    }
}
