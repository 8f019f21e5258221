package org.ripv.server.http;

import com.sun.net.httpserver.HttpExchange;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Landing-page sessions after a log-in: a random id in an HttpOnly, SameSite=Strict cookie, a
 * separate random CSRF token the upload form must send back, half an hour of life, and per-visitor
 * limits on what one session may upload. Bounded: the oldest session goes when there are too many.
 */
final class WebSessions {
    static final String COOKIE = "ripv-session";
    static final long LIFE_MILLIS = 30 * 60_000;
    static final int MAX_SESSIONS = 1000;
    /** Files one session may upload. */
    static final int MAX_FILES = 100;

    private static final SecureRandom RANDOM = new SecureRandom();

    /** One logged-in visitor. */
    static final class Session {
        final String id = random();
        final String csrf = random();
        final String user;
        final long expires = System.currentTimeMillis() + LIFE_MILLIS;
        long bytes;
        int files;

        Session(String user) {
            this.user = user;
        }
    }

    private final Map<String, Session> sessions = new LinkedHashMap<>();

    synchronized Session create(String user) {
        if (sessions.size() >= MAX_SESSIONS) {
            sessions.remove(sessions.keySet().iterator().next());
        }
        Session s = new Session(user);
        sessions.put(s.id, s);
        return s;
    }

    /** The visitor's session from the request's cookie, or null. */
    synchronized Session find(HttpExchange ex) {
        List<String> cookies = ex.getRequestHeaders().get("Cookie");
        if (cookies == null) {
            return null;
        }
        for (String header : cookies) {
            for (String c : header.split(";")) {
                String[] kv = c.trim().split("=", 2);
                if (kv.length == 2 && kv[0].equals(COOKIE)) {
                    Session s = sessions.get(kv[1]);
                    if (s != null && s.expires < System.currentTimeMillis()) {
                        sessions.remove(kv[1]);
                        return null;
                    }
                    if (s != null) {
                        return s;
                    }
                }
            }
        }
        return null;
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

    static String cookie(Session s, boolean secure) {
        return COOKIE + "=" + s.id + "; Path=/; HttpOnly; SameSite=Strict; Max-Age=" + LIFE_MILLIS / 1000
                + (secure ? "; Secure" : "");
    }

    private static String random() {
        byte[] b = new byte[24];
        RANDOM.nextBytes(b);
        return HexFormat.of().formatHex(b);
    }
}
