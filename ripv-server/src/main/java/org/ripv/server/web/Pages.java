package org.ripv.server.web;

import java.net.URI;
import java.util.Locale;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.io.Content;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;

/** Small HTML answers, escaping, and the same-origin test every state change passes. */
final class Pages {
    private Pages() {}

    static void fail(Response response, Callback callback, int status, String title, String text) {
        send(response, callback, status, "text/html; charset=utf-8", page("Error: " + title, "<p id=\"error\" role=\"alert\">"
                + html(text) + "</p><p><a href=\"/\">Back</a></p>"));
    }

    /** A page in the console's style: the one stylesheet, no script. */
    static String page(String title, String body) {
        return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                + "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>" + html(title)
                + "</title><link rel=\"stylesheet\" href=\"/ripv.css\"></head><body><main><h1>" + html(title) + "</h1>\n"
                + body + "\n</main></body></html>\n";
    }

    static void send(Response response, Callback callback, int status, String type, String body) {
        response.setStatus(status);
        response.getHeaders().put(HttpHeader.CONTENT_TYPE, type);
        Content.Sink.write(response, true, body, callback);
    }

    static void redirect(Response response, Callback callback, String location) {
        response.getHeaders().put(HttpHeader.LOCATION, location);
        send(response, callback, 303, "text/html; charset=utf-8", page("See other", "<p><a href=\"" + html(location)
                + "\">Continue</a></p>"));
    }

    static String html(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;").replace("'", "&#39;");
    }

    /**
     * Why a state-changing request is not from this server's own pages, or null when it is: a
     * browser sends {@code Origin} (and {@code Sec-Fetch-Site}) with every cross-site POST and
     * WebSocket; a request without them is not a browser's and carries no ambient cookie risk.
     */
    static String crossOrigin(Request request) {
        String site = request.getHeaders().get("Sec-Fetch-Site");
        if (site != null && !site.equals("same-origin") && !site.equals("none")) {
            return "the request came from another site (Sec-Fetch-Site: " + site + ")";
        }
        String origin = request.getHeaders().get(HttpHeader.ORIGIN);
        if (origin == null) {
            return null;
        }
        String scheme = request.isSecure() ? "https" : "http";
        try {
            URI o = URI.create(origin);
            int port = o.getPort() != -1 ? o.getPort() : "https".equals(o.getScheme()) ? 443 : 80;
            if (scheme.equals(o.getScheme()) && o.getHost() != null
                    && o.getHost().toLowerCase(Locale.ROOT).equals(Request.getServerName(request).toLowerCase(Locale.ROOT))
                    && port == Request.getServerPort(request)) {
                return null;
            }
        } catch (IllegalArgumentException e) {
            // not a URI: not our origin
        }
        return "the request came from another origin (" + origin + ")";
    }
}
