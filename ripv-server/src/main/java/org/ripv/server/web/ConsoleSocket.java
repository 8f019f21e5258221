package org.ripv.server.web;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.concurrent.atomic.AtomicInteger;
import org.eclipse.jetty.websocket.api.Callback;
import org.eclipse.jetty.websocket.api.Session;
import org.eclipse.jetty.websocket.common.WebSocketSession;
import org.eclipse.jetty.websocket.core.CoreSession;
import org.eclipse.jetty.websocket.core.Frame;
import org.eclipse.jetty.websocket.core.OpCode;
import org.eclipse.jetty.websocket.core.WebSocketConnection;
import org.eclipse.jetty.websocket.core.WebSocketCoreSession;
import org.ripv.messages.Attachment;
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
 * and console push goes back as JSON ({@link WebReplies}) with Jetty's asynchronous send. A push
 * every watching page gets is one UTF-8 buffer ({@link PushJson}) that each page's frame shares
 * (issue 38: no copy per page).
 *
 * <p>What waits for a page is bounded: at most {@link #MAX_PUSHES} pushes not yet written (beyond
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

    private final WebSessions sessions;
    private final WebSessions.Session login;
    private final PostOfficeDoor door;
    private final PushJson json;
    private final InetAddress address;
    private final AtomicInteger queued = new AtomicInteger();
    private volatile Session socket;
    /** The socket's core session, where a shared push's frame goes (set with {@link #socket}). */
    private volatile CoreSession core;
    /**
     * True when the page negotiated an extension (permessage-deflate): then each push gets a frame
     * of its own over a slice of the shared bytes, which no extension can then move ({@link PushJson}).
     */
    private volatile boolean extended;
    /**
     * Where a page without an extension has its shared pushes queued: straight on its connection's
     * frame flusher, the one every frame of the page ends in. The core session's path before it
     * (its state's lock, the transforming flusher's lock and queue, fragmenting, the empty extension
     * stack) does nothing for a finished text frame to such a page, and took a tenth of the
     * server's CPU per delivery (docs/performance.md). Replies take this path too, so that nothing
     * RIPV sends overtakes anything it sent before; only Jetty's own frames (pong, close) take the
     * session's. The flusher refuses a frame once the close frame is queued, failing its callback,
     * as the session's own check would. Null when the page negotiated an extension, or Jetty's
     * session is not the core one this was written against.
     */
    private volatile WebSocketConnection direct;
    /** The callback of frames no one waits for (replies); one per page. */
    private final Written replied = new Written(null);
    /**
     * The callback of the last watcher's pushes: a watcher's "written" is one object for its life
     * and a page mostly watches one vehicle at a time, so this saves a callback per push (issue 38).
     */
    private volatile Written lastWritten = replied;
    /**
     * False once the page's socket closed or is being closed: checked per push without asking
     * Jetty, whose own check takes the session's lock (the frame's send checks again).
     */
    private volatile boolean open;
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
        this.core = ((WebSocketSession) session).getCoreSession();
        this.extended = !core.getNegotiatedExtensions().isEmpty();
        this.direct = !extended && core instanceof WebSocketCoreSession c ? c.getConnection() : null;
        this.socket = session;
        String refused = sessions.admitSocket(login, this);
        if (refused != null) {
            log.info("web console socket of {} from {} refused: {}", login.user, address.getHostAddress(), refused);
            session.close(1008, truncate(refused), Callback.NOOP);
            return;
        }
        this.open = true;
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
                Attachment chunk = FileChunks.attachment(m);
                c.received(new IncomingServerMessage(chunk == null ? h : h.withAttachment(chunk)));
            }
        } catch (IOException | IllegalArgumentException e) {
            sendText(error("could not send: " + e.getMessage()), null);
        }
    }

    @Override
    public boolean send(OutgoingServerMessage reply) {
        return reply.header().messageId() == 0 ? sendShared(json.of(reply), null) : sendText(json.reply(reply), null);
    }

    /**
     * A push: refused while {@link #MAX_PUSHES} frames are queued. The console hub's watcher keeps
     * fewer than that in flight and holds the rest itself (a refused push would be lost to this
     * page, so no tighter rule may refuse one here: a cap on bytes did, and lost lines silently).
     */
    @Override
    public boolean push(OutgoingServerMessage message, Runnable written) {
        if (queued.get() >= MAX_PUSHES) {
            return false;
        }
        return sendShared(json.of(message), written);
    }

    @Override
    public InetAddress address() {
        return address;
    }

    /** Queues one frame; false when the socket is closed or too much waits (the page is then cut off). */
    private boolean sendText(String text, Runnable written) {
        Session s = socket;
        if (s == null || !s.isOpen() || !admit()) {
            return false;
        }
        WebSocketConnection d = direct;
        if (d != null) {
            // The pushes' path: a reply and the pushes after it (a watch's replay, then its live
            // lines) leave in the order they were sent.
            d.enqueueFrame(new Frame(OpCode.TEXT, text), written == null ? replied : new Written(written), false);
            return true;
        }
        s.sendText(text, new Callback() {
            @Override
            public void succeed() {
                ConsoleSocket.this.written(written);
            }

            @Override
            public void fail(Throwable x) {
                ConsoleSocket.this.failed(x);
            }
        });
        return true;
    }

    /**
     * Queues a text frame that other pages share: every page without an extension gets the very
     * frame, queued on its connection ({@link #direct}), whose payload nothing on the way moves or
     * writes into (a server's frames are not masked; Jetty's flusher writes a slice), instead of
     * its own UTF-8 copy of the text; a page with permessage-deflate gets a frame over a slice of
     * the same bytes through its core session, whose deflater may consume it.
     */
    private boolean sendShared(Frame shared, Runnable written) {
        CoreSession s = core;
        if (s == null || !open || !admit()) {
            return false;
        }
        Written callback = lastWritten;
        if (callback.then != written) {
            callback = written == null ? replied : new Written(written);
            lastWritten = callback;
        }
        WebSocketConnection d = direct;
        if (d != null) {
            d.enqueueFrame(shared, callback, false);
        } else {
            s.sendFrame(extended ? new Frame(OpCode.TEXT, shared.getPayload().slice()) : shared, callback, false);
        }
        return true;
    }

    /** What runs when a frame has been written or failed: holds nothing of one frame, so a page reuses it. */
    private final class Written implements org.eclipse.jetty.util.Callback {
        final Runnable then;

        Written(Runnable then) {
            this.then = then;
        }

        @Override
        public void succeeded() {
            written(then);
        }

        @Override
        public void failed(Throwable x) {
            ConsoleSocket.this.failed(x);
        }
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

    private void written(Runnable then) {
        queued.decrementAndGet();
        if (then != null) {
            then.run();
        }
    }

    private void failed(Throwable x) {
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
        open = false;
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

    /** What a page is told when its message could not be sent: {@code {"type":"error","text":...}}. */
    private static String error(String text) {
        try {
            return JSON.writeValueAsString(JSON.createObjectNode().put("type", "error").put("text", text));
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("an error could not be written as JSON", e);
        }
    }

    private static String truncate(String s) {
        return s.length() > 100 ? s.substring(0, 100) : s;
    }
}
