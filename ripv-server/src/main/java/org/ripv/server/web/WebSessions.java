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
 * Bounded per user and in all (issue 33 items 2 and 3): a user's new log-in past
 * {@link #MAX_SESSIONS_PER_USER} ends that user's own oldest session, never another user's; with
 * {@link #MAX_SESSIONS} live a log-in is refused; a session opens at most
 * {@link #MAX_SOCKETS_PER_SESSION} WebSockets and a user at most {@link #MAX_SOCKETS_PER_USER}, so one
 * log-in cannot take the server's client places. Expired sessions are swept (their sockets closed).
 */
final class WebSessions {
    static final String COOKIE = "ripv-session";
    static final int MAX_SESSIONS = 1000;
    /** Browsers (devices, profiles) one user may be logged in from at once. */
    static final int MAX_SESSIONS_PER_USER = 16;
    /** Pages (tabs) one log-in may have open by default: each page is one WebSocket and one Post Office client. */
    static final int MAX_SOCKETS_PER_SESSION = 32;
    /** Pages one user may have open over all their log-ins by default ({@code --web-pages}). */
    static final int MAX_SOCKETS_PER_USER = 64;
    private volatile int socketsPerSession = MAX_SOCKETS_PER_SESSION;
    private volatile int socketsPerUser = MAX_SOCKETS_PER_USER;
    /** Files one session may upload. */
    static final int MAX_FILES = 100;

    private static final SecureRandom RANDOM = new SecureRandom();

    /** One logged-in browser. */
    static final class Session {
        final String id = random();
        final String csrf = random();
        final String user;
        /** Re-derived when the permit file changes (item 4): the next page and every request use the new roles. */
        volatile List<String> roles;
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

    /**
     * A new session for a log-in, or null when {@link #MAX_SESSIONS} are live (the log-in is refused:
     * no other user's session is ended to make room). The user's own oldest session ends when they
     * already have {@link #MAX_SESSIONS_PER_USER}.
     */
    synchronized Session create(String user, List<String> roles) {
        sweep();
        List<Session> own = sessions.values().stream().filter(x -> x.user.equals(user)).toList(); // oldest first
        for (int i = 0; i <= own.size() - MAX_SESSIONS_PER_USER; i++) {
            end(own.get(i).id);
        }
        if (sessions.size() >= MAX_SESSIONS) {
            return null;
        }
        Session s = new Session(user, roles, clock.getAsLong());
        sessions.put(s.id, s);
        return s;
    }

    /** Pages one user may have open ({@code --web-pages}); one log-in at most half of it. */
    void pagesPerUser(int n) {
        socketsPerUser = n;
        socketsPerSession = Math.max(1, n / 2);
    }

    /** Ends every expired session, closing its pages' WebSockets (a page of an expired log-in gets no more pushes). */
    synchronized int sweep() {
        long now = clock.getAsLong();
        List<String> expired = sessions.values().stream()
                .filter(s -> now - s.lastSeen > idleMillis || now - s.created > absoluteMillis).map(s -> s.id).toList();
        expired.forEach(this::end);
        return expired.size();
    }

    /**
     * Why the session may open no further WebSocket, or null. {@code socket} non-null: it is counted
     * now (atomically with the check); null: only asked (before the upgrade, so a refusal costs little).
     */
    synchronized String admitSocket(Session s, AutoCloseable socket) {
        if (sessions.get(s.id) != s) {
            return "the session has ended; log in again";
        }
        if (socket != null && s.sockets.contains(socket)) {
            return null;
        }
        if (s.sockets.size() >= socketsPerSession) {
            return "this log-in has " + socketsPerSession + " pages open, the most it may; close one and reload";
        }
        int mine = sessions.values().stream().filter(x -> x.user.equals(s.user)).mapToInt(x -> x.sockets.size()).sum();
        if (mine >= socketsPerUser) {
            return s.user + " has " + socketsPerUser + " pages open over all log-ins, the most a user may; close one and reload";
        }
        if (socket != null) {
            s.sockets.add(socket);
        }
        return null;
    }

    /** Ends the sessions of {@code ended} users; gives the sessions of users in {@code roles} their new roles. */
    synchronized void usersChanged(Set<String> ended, Map<String, List<String>> roles) {
        for (Session s : List.copyOf(sessions.values())) {
            if (ended.contains(s.user)) {
                end(s.id);
            } else if (roles.containsKey(s.user)) {
                s.roles = List.copyOf(roles.get(s.user));
            }
        }
    }

    /** The live sessions of a user. */
    synchronized List<Session> of(String user) {
        return sessions.values().stream().filter(x -> x.user.equals(user)).toList();
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
