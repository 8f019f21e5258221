package org.ripv.server.web;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import org.eclipse.jetty.websocket.api.Callback;
import org.eclipse.jetty.websocket.api.Session;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.wire.FrameCodec;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One page's WebSocket ({@code /ws}): a Post Office client. The page sends
 * {@code {"id":7,"mailbox":"…","body":"dir","priority":"normal","csrf":"…"}} (an upload chunk adds
 * {@code "file"} and {@code "data"}, see {@link FileChunks}); this forwards it
 * unchanged over its {@link PostOfficeLink}, so the server's own rules decide; every reply and
 * console push goes back as JSON ({@link WebReplies}). A browser that stops reading fills Jetty's
 * bounded outgoing queue and is disconnected; the link's own reply queue in the server is bounded
 * the same way, so a stalled page slows nobody. (Public only because Jetty calls its listener methods
 * reflectively; nothing outside this package makes one.)
 */
public final class ConsoleSocket implements Session.Listener.AutoDemanding, AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(ConsoleSocket.class);
    private static final ObjectMapper JSON = new ObjectMapper();

    private final WebSessions sessions;
    private final WebSessions.Session login;
    private final PostOfficeDoor door;
    private final FrameCodec codec;
    private final String address;
    private final WebReplies replies = new WebReplies();
    private volatile Session socket;
    private volatile PostOfficeLink link;

    ConsoleSocket(WebSessions sessions, WebSessions.Session login, PostOfficeDoor door, FrameCodec codec, String address) {
        this.sessions = sessions;
        this.login = login;
        this.door = door;
        this.codec = codec;
        this.address = address;
    }

    @Override
    public void onWebSocketOpen(Session session) {
        this.socket = session;
        login.sockets.add(this);
        try {
            link = new PostOfficeLink(door.open(login.user, login.roles, address), codec, login.user, this::deliver, this::close);
        } catch (IOException e) {
            session.close(1013, truncate("the server takes no more clients: " + e.getMessage()), Callback.NOOP);
        }
    }

    @Override
    public void onWebSocketText(String text) {
        if (!sessions.live(login)) {
            close(1008, "the session has ended; log in again");
            return;
        }
        try {
            JsonNode m = JSON.readTree(text);
            if (!login.csrf(m.path("csrf").asText(null))) {
                close(1008, "no or a wrong CSRF token");
                return;
            }
            sessions.find(login.id); // the user acted: the session is not idle
            PostOfficeLink l = link;
            if (l != null) {
                l.send(m.path("id").asLong(), m.path("mailbox").asText(""), m.path("body").asText(""),
                        Priority.parse(m.path("priority").asText("normal")), FileChunks.attachment(m));
            }
        } catch (IOException | IllegalArgumentException e) {
            sendJson("{\"type\":\"error\",\"text\":" + quote("could not send: " + e.getMessage()) + "}");
        }
    }

    private void deliver(OutgoingServerMessage m) {
        sendJson(replies.toJson(m));
    }

    private void sendJson(String json) {
        Session s = socket;
        if (s == null || !s.isOpen()) {
            return;
        }
        s.sendText(json, new Callback() {
            @Override
            public void fail(Throwable x) {
                // Too many frames queued (the page stopped reading) or the socket broke: cut it off.
                log.info("web console socket of {} closed: {}", login.user, x.toString());
                ConsoleSocket.this.close();
            }
        });
    }

    @Override
    public void onWebSocketClose(int statusCode, String reason) {
        close();
    }

    @Override
    public void onWebSocketError(Throwable cause) {
        close();
    }

    private void close(int code, String reason) {
        Session s = socket;
        if (s != null && s.isOpen()) {
            s.close(code, reason, Callback.NOOP);
        }
        close();
    }

    /** Ends the page's socket and its Post Office client. */
    @Override
    public void close() {
        login.sockets.remove(this);
        PostOfficeLink l = link;
        if (l != null) {
            l.close();
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
