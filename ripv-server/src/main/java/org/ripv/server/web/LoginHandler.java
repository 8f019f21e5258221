package org.ripv.server.web;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.charset.StandardCharsets;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.io.Content;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;
import org.eclipse.jetty.util.Fields;
import org.eclipse.jetty.util.UrlEncoded;
import org.ripv.server.web.WebSessions.Session;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code POST /login}, {@code POST /logout} and {@code GET /api/session}. A log-in is taken only
 * as a form from this server's own page (no {@code text/plain}, no other origin: log-in CSRF,
 * issue 23 item 10), checked by {@link WebAccess} with the socket port's throttle and audit, and
 * always starts a new session — whatever session id the browser brought is ended, not kept.
 */
final class LoginHandler extends Handler.Abstract {
    private static final Logger log = LoggerFactory.getLogger(LoginHandler.class);
    static final int MAX_FORM_BYTES = 4096;

    private final WebAccess access;
    private final WebSessions sessions;
    private final boolean secure;
    private final Map<String, Object> pageSettings;
    private final ObjectMapper json = new ObjectMapper();

    LoginHandler(WebAccess access, WebSessions sessions, boolean secure, Map<String, Object> pageSettings) {
        this.access = access;
        this.sessions = sessions;
        this.secure = secure;
        this.pageSettings = Collections.unmodifiableMap(new LinkedHashMap<>(pageSettings));
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) throws Exception {
        String path = Request.getPathInContext(request);
        switch (path) {
            case "/login" -> login(request, response, callback);
            case "/logout" -> logout(request, response, callback);
            case "/api/session" -> session(request, response, callback);
            default -> {
                return false;
            }
        }
        return true;
    }

    private void login(Request request, Response response, Callback callback) {
        if (!"POST".equals(request.getMethod())) {
            Pages.redirect(response, callback, "/");
            return;
        }
        String type = request.getHeaders().get(HttpHeader.CONTENT_TYPE);
        if (type == null || !type.split(";")[0].trim().equalsIgnoreCase("application/x-www-form-urlencoded")) {
            response.getHeaders().put(HttpHeader.CONNECTION, "close"); // its body is not read
            Pages.fail(response, callback, 415, "Not a log-in form", "A log-in must come from the form on this server's"
                    + " page (application/x-www-form-urlencoded), not '" + (type == null ? "no content type" : type) + "'.");
            return;
        }
        String cross = Pages.crossOrigin(request);
        if (cross != null) {
            log.info("web log-in refused from {}: {}", Request.getRemoteAddr(request), cross);
            response.getHeaders().put(HttpHeader.CONNECTION, "close");
            Pages.fail(response, callback, 403, "Log-in refused", "Log in on this server's own page: " + cross + ".");
            return;
        }
        String address = Request.getRemoteAddr(request);
        Session before = sessions.find(request);
        form(request).whenComplete((fields, failure) -> {
            if (failure != null) {
                Pages.fail(response, callback, 400, "Bad log-in form", "The form could not be read: " + failure.getMessage());
                return;
            }
            // The password check waits for the log-in pool: not on Jetty's selector threads.
            request.getContext().execute(() -> check(fields, address, before, response, callback));
        });
    }

    private void check(Fields fields, String address, Session before, Response response, Callback callback) {
        String user = fields.getValue("user");
        String password = fields.getValue("password");
        WebAccess.Result r = access.login(user == null ? "" : user.trim(), password == null ? new char[0] : password.toCharArray(), address);
        if (r.user() == null) {
            Pages.fail(response, callback, 403, "Log-in refused", r.refusal());
            return;
        }
        if (before != null) {
            sessions.end(before.id); // never carried over a log-in: a planted id dies here
        }
        Session s = sessions.create(r.user(), r.roles());
        if (s == null) {
            log.warn("web log-in of {} refused: {} web sessions are open, the most this server keeps", r.user(), WebSessions.MAX_SESSIONS);
            Pages.fail(response, callback, 503, "Log-in refused", "This server has " + WebSessions.MAX_SESSIONS
                    + " web log-ins open, the most it keeps; try again in a few minutes (idle ones end after "
                    + WebConsole.SESSION_IDLE.toMinutes() + " minutes) or use the RIPV client.");
            return;
        }
        response.getHeaders().add(HttpHeader.SET_COOKIE, sessions.cookie(s, secure));
        Pages.redirect(response, callback, "/fleet.html");
    }

    private void logout(Request request, Response response, Callback callback) {
        if (!"POST".equals(request.getMethod())) {
            response.getHeaders().put(HttpHeader.ALLOW, "POST");
            Pages.send(response, callback, 405, "text/plain; charset=utf-8", "log out with the button on a page (POST)\n");
            return;
        }
        Session s = sessions.find(request);
        String cross = Pages.crossOrigin(request);
        form(request).whenComplete((fields, failure) -> {
            if (s == null) {
                response.getHeaders().add(HttpHeader.SET_COOKIE, WebSessions.expiredCookie(secure));
                Pages.redirect(response, callback, "/");
            } else if (cross != null || failure != null || !s.csrf(fields.getValue("csrf"))) {
                Pages.fail(response, callback, 403, "Log-out refused", "The log-out did not come from this server's own page"
                        + " (no or a wrong CSRF token); use the Log out button.");
            } else {
                sessions.end(s.id);
                log.info("web session of {} logged out", s.user);
                response.getHeaders().add(HttpHeader.SET_COOKIE, WebSessions.expiredCookie(secure));
                Pages.redirect(response, callback, "/");
            }
        });
    }

    /** The form's fields, read without holding a thread while a slow body arrives; at most {@link #MAX_FORM_BYTES}. */
    private static CompletableFuture<Fields> form(Request request) {
        long length = request.getLength();
        if (length < 0 || length > MAX_FORM_BYTES) {
            return CompletableFuture.failedFuture(
                    new IllegalArgumentException("a form of " + (length < 0 ? "unknown length" : length + " bytes") + "; at most " + MAX_FORM_BYTES + " are read"));
        }
        return Content.Source.asStringAsync(request, StandardCharsets.UTF_8).thenApply(body -> {
            if (body.length() > MAX_FORM_BYTES) {
                throw new IllegalArgumentException("a form over " + MAX_FORM_BYTES + " bytes");
            }
            Fields fields = new Fields();
            UrlEncoded.decodeUtf8To(body, fields);
            return fields;
        });
    }

    /** What a page needs to know about its log-in: who, their roles, the CSRF token, the console's settings. */
    private void session(Request request, Response response, Callback callback) throws Exception {
        Session s = sessions.find(request);
        if (s == null) {
            Pages.send(response, callback, 401, "application/json", json.writeValueAsString(Map.of("error", "log in first")));
            return;
        }
        Map<String, Object> m = new LinkedHashMap<>(pageSettings);
        m.put("user", s.user);
        m.put("roles", s.roles);
        m.put("csrf", s.csrf);
        Pages.send(response, callback, 200, "application/json", json.writeValueAsString(m));
    }
}
