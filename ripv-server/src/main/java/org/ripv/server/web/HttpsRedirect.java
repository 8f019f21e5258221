package org.ripv.server.web;

import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.http.HttpURI;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;

/**
 * Plain {@code http://} on the HTTPS port: the connector tells TLS from plain HTTP by the first
 * bytes ({@code DetectorConnectionFactory}), and a plain request is sent to the same address under
 * {@code https://} (308, so a form's POST stays a POST) instead of reading TLS garbage. Nothing
 * else is served without TLS: no page, no session cookie, no WebSocket.
 */
final class HttpsRedirect extends Handler.Wrapper {

    HttpsRedirect(Handler next) {
        super(next);
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) throws Exception {
        if (request.isSecure()) {
            return super.handle(request, response, callback);
        }
        String to = HttpURI.build(request.getHttpURI()).scheme("https").host(Request.getServerName(request))
                .port(Request.getServerPort(request)).asString();
        response.getHeaders().put(HttpHeader.LOCATION, to);
        response.getHeaders().put(HttpHeader.CONNECTION, "close");
        Pages.send(response, callback, 308, "text/html; charset=utf-8", Pages.page("This console speaks HTTPS",
                "<p>Open <a href=\"" + Pages.html(to) + "\">" + Pages.html(to) + "</a>.</p>"));
        return true;
    }
}
