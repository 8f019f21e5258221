package org.ripv.server.web;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.LinkedHashMap;
import java.util.Map;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code GET /api/public}: the public view's data for anonymous visitors ({@link PublicFleet}); no
 * session, no cookie, read only. Without {@code --public} it answers 404 like any unknown path.
 */
final class PublicHandler extends Handler.Abstract {
    private static final Logger log = LoggerFactory.getLogger(PublicHandler.class);
    private final PublicFleet fleet;
    private final String tiles;
    private final ObjectMapper json = new ObjectMapper();

    /** @param fleet the vehicles shown, or null: no public view */
    PublicHandler(PublicFleet fleet, String mapTiles) {
        this.fleet = fleet;
        this.tiles = mapTiles;
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) {
        if (!"/api/public".equals(Request.getPathInContext(request))) {
            return false;
        }
        if (fleet == null) {
            Pages.send(response, callback, 404, "text/plain; charset=utf-8",
                    "no public view on this server (the operator turns it on with --public GLOB)\n");
            return true;
        }
        if (!"GET".equals(request.getMethod())) {
            response.getHeaders().put(HttpHeader.ALLOW, "GET");
            Pages.send(response, callback, 405, "text/plain; charset=utf-8", "the public view is read only (GET)\n");
            return true;
        }
        fleet.vehicles().whenComplete((vehicles, failure) -> {
            if (failure != null) {
                log.info("public view: {}", failure.toString());
                Pages.send(response, callback, 503, "application/json", error("the vehicles could not be read now; try again"));
                return;
            }
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("mapTiles", tiles);
            m.put("vehicles", vehicles);
            try {
                Pages.send(response, callback, 200, "application/json", json.writeValueAsString(m));
            } catch (JsonProcessingException e) {
                Pages.send(response, callback, 500, "application/json", error("could not write the vehicles"));
            }
        });
        return true;
    }

    /** {@code {"error":TEXT}}, written by the same mapper (a constant text: it cannot fail to write). */
    private String error(String text) {
        return json.createObjectNode().put("error", text).toString();
    }
}
