package org.ripv.server.web;

import org.eclipse.jetty.http.HttpFields;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;

/**
 * The headers every answer carries: a Content-Security-Policy that runs only this server's own
 * script files (no inline script, no eval), never framed; no sniffing; no referrer to other sites; and, under
 * TLS, HSTS. Map tiles, when the operator gives a tile server, are the one outside source.
 */
final class SecurityHeaders extends Handler.Wrapper {
    private final String csp;
    private final boolean tls;

    /** @param tileOrigin the origin of the operator's map tiles ({@code https://tile.example.org}), or null */
    SecurityHeaders(Handler next, boolean tls, String tileOrigin) {
        super(next);
        this.tls = tls;
        this.csp = "default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data: blob:"
                + (tileOrigin == null ? "" : " " + tileOrigin)
                + "; connect-src 'self'; object-src 'none'; base-uri 'none'; frame-ancestors 'none'; form-action 'self'";
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) throws Exception {
        HttpFields.Mutable h = response.getHeaders();
        h.put("Content-Security-Policy", csp);
        h.put("X-Content-Type-Options", "nosniff");
        h.put("Referrer-Policy", "same-origin"); // not no-referrer: Chromium then sends "Origin: null" with our own forms
        h.put("X-Frame-Options", "DENY");
        h.put("Cache-Control", "no-store");
        if (tls) {
            h.put("Strict-Transport-Security", "max-age=31536000");
        }
        return super.handle(request, response, callback);
    }
}
