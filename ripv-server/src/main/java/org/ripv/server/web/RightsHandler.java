package org.ripv.server.web;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;
import org.eclipse.jetty.util.Fields;

/**
 * {@code GET /api/rights?m=MAILBOX&c=COMMAND...}: what the permit file lets the logged-in user send
 * to a MailBox ({@code m} empty: the server), so a page shows an observer the controls their rules
 * allow and not the ones a role's name suggests. Read only; the server decides every command again
 * when it is sent, so a wrong answer here can hide a button, never grant a right.
 */
final class RightsHandler extends Handler.Abstract {
    /** Commands one question may ask about, and their length: a page asks about a handful. */
    static final int MAX_COMMANDS = 16;
    static final int MAX_LENGTH = 300;

    private final WebAccess access;
    private final WebSessions sessions;
    private final ObjectMapper json = new ObjectMapper();

    RightsHandler(WebAccess access, WebSessions sessions) {
        this.access = access;
        this.sessions = sessions;
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) throws Exception {
        if (!"/api/rights".equals(Request.getPathInContext(request))) {
            return false;
        }
        if (!"GET".equals(request.getMethod())) {
            response.getHeaders().put(HttpHeader.ALLOW, "GET");
            Pages.send(response, callback, 405, "text/plain; charset=utf-8", "/api/rights is read only (GET)\n");
            return true;
        }
        WebSessions.Session s = sessions.find(request);
        if (s == null) {
            Pages.send(response, callback, 401, "application/json", json.writeValueAsString(Map.of("error", "log in first")));
            return true;
        }
        Fields query = Request.extractQueryParameters(request);
        String mailbox = query.getValue("m") == null ? "" : query.getValue("m");
        List<String> commands = query.getValuesOrEmpty("c");
        if (commands.size() > MAX_COMMANDS || mailbox.length() > MAX_LENGTH
                || commands.stream().anyMatch(c -> c.length() > MAX_LENGTH)) {
            Pages.send(response, callback, 400, "application/json", json.writeValueAsString(Map.of("error",
                    "at most " + MAX_COMMANDS + " commands of at most " + MAX_LENGTH + " characters")));
            return true;
        }
        WebAccess.Rights r = access.rights(s.user, mailbox, commands);
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("mailbox", mailbox);
        m.put("send", r.send());
        m.put("commands", r.commands());
        Pages.send(response, callback, 200, "application/json", json.writeValueAsString(m));
        return true;
    }
}
