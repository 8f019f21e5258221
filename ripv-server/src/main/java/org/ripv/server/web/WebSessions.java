package org.ripv.server.web;

import java.security.MessageDigest;
import java.security.SecureRandom;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.LongSupplier;
import org.eclipse.jetty.http.HttpCookie;
import org.eclipse.jetty.server.Request;

/**
 * Browser sessions after a log-in: a random id in a Secure (under TLS), HttpOnly,
 * SameSite=Strict cookie; a separate random CSRF token every state change must send back; an
 * idle and an absolute expiry; the pages' open WebSockets, closed when the session ends. A
 * session id is only ever made here at a log-in, so an id planted before it is never kept.
 * Bounded: the oldest session goes when there are too many.
 */
final class WebSessions {
    static final String COOKIE = "ripv-session";
    static final int MAX_SESSIONS = 1000;
    /** Files one session may upload. */
    static final int MAX_FILES = 100;

    private static final SecureRandom RANDOM = new SecureRandom();

    /** One logged-in browser. */
    static final class Session {
        final String id = random();
        final String csrf = random();
        final String user;
        final List<String> roles;
        final long created;
        volatile long lastSeen;
        long bytes;
        int files;
        final Set<AutoCloseable> sockets = ConcurrentHashMap.newKeySet();

        Session(String user, List<String> roles, long now) {
            this.user = user;
            this.roles = List.copyOf(roles);
            this.created = now;
            this.lastSeen = now;
        }

        /** True when {@code token} is this session's CSRF token (compared in constant time). */
        boolean csrf(String token) {
            return token != null && MessageDigest.isEqual(csrf.getBytes(StandardCharsets.UTF_8), token.getBytes(StandardCharsets.UTF_8));
        }
    }

    private final Map<String, Session> sessions = new LinkedHashMap<>();
    private final long idleMillis;
    private final long absoluteMillis;
    private final LongSupplier clock;

    WebSessions(Duration idle, Duration absolute, LongSupplier clock) {
        this.idleMillis = idle.toMillis();
        this.absoluteMillis = absolute.toMillis();
        this.clock = clock;
    }

    synchronized Session create(String user, List<String> roles) {
        if (sessions.size() >= MAX_SESSIONS) {
            end(sessions.keySet().iterator().next());
        }
        Session s = new Session(user, roles, clock.getAsLong());
        sessions.put(s.id, s);
        return s;
    }

    /** The live session the request's cookie names (touching it), or null. */
    Session find(Request request) {
        List<HttpCookie> cookies = Request.getCookies(request);
        for (HttpCookie c : cookies) {
            if (COOKIE.equals(c.getName())) {
                Session s = find(c.getValue());
                if (s != null) {
                    return s;
                }
            }
        }
        return null;
    }

    /** The live session with this id (touching it), or null; an expired one is ended. */
    synchronized Session find(String id) {
        Session s = sessions.get(id);
        if (s == null) {
            return null;
        }
        long now = clock.getAsLong();
        if (now - s.lastSeen > idleMillis || now - s.created > absoluteMillis) {
            end(id);
            return null;
        }
        s.lastSeen = now;
        return s;
    }

    /** True while the session is live, without counting as activity (a console push is not the user). */
    synchronized boolean live(Session s) {
        long now = clock.getAsLong();
        return sessions.get(s.id) == s && now - s.lastSeen <= idleMillis && now - s.created <= absoluteMillis;
    }

    /** Ends a session: forgotten, and its pages' WebSockets closed. */
    synchronized void end(String id) {
        Session s = sessions.remove(id);
        if (s != null) {
            for (AutoCloseable c : s.sockets) {
                try {
                    c.close();
                } catch (Exception ignored) {
                    // closing anyway
                }
            }
            s.sockets.clear();
        }
    }

    /** Counts an upload against the session's limits; false when it would go over them. */
    synchronized boolean charge(Session s, int files, long bytes, long maxBytes) {
        if (s.files + files > MAX_FILES || s.bytes + bytes > maxBytes) {
            return false;
        }
        s.files += files;
        s.bytes += bytes;
        return true;
    }

    String cookie(Session s, boolean secure) {
        return COOKIE + "=" + s.id + "; Path=/; HttpOnly; SameSite=Strict; Max-Age=" + absoluteMillis / 1000
                + (secure ? "; Secure" : "");
    }

    static String expiredCookie(boolean secure) {
        return COOKIE + "=; Path=/; HttpOnly; SameSite=Strict; Max-Age=0" + (secure ? "; Secure" : "");
    }

    private static String random() {
        byte[] b = new byte[24];
        RANDOM.nextBytes(b);
        return HexFormat.of().formatHex(b);
    }
}
