package org.ripv.server.web;

import org.ripv.launch.OptionChecks;
import org.ripv.server.security.SecuritySettings;
import picocli.CommandLine.Option;

/**
 * {@code ripv server}'s options for the landing page and the web console (a picocli mixin):
 * uploads there, pages a user may keep open, the map's tiles and what anonymous visitors see.
 */
public final class WebOptions {
    @Option(names = "--http-upload", description = "Let users who log in on the landing page upload files (off by default;"
            + " the permit file's ?upload rules apply).")
    boolean httpUpload;

    @Option(names = "--web-pages", paramLabel = "N", defaultValue = "64", description = "Web console pages (WebSockets) one user"
            + " may have open over all their log-ins; one log-in half of it (default ${DEFAULT-VALUE}).")
    int webPages;

    @Option(names = "--map-tiles", paramLabel = "URL", description = "Map tiles for the web console's map, an https URL with {z}, {x}"
            + " and {y} (default: none; the map is a latitude/longitude grid that needs no internet).")
    String mapTiles;

    @Option(names = "--public", paramLabel = "GLOB", description = "Show anonymous visitors of the web console the map, track and"
            + " last contact of the vehicles whose names match, e.g. 'glider*' (off by default).")
    String publicNames;

    /** Refuses fewer than two pages a user (one log-in gets half). */
    public void checkPages() {
        OptionChecks.atLeast("--web-pages", webPages, 2);
    }

    /** Refuses a tile URL the console would not load and a glob that is not one, each with its reason. */
    public void checkTilesAndPublic() {
        WebConsole.checkMapTiles(mapTiles);
        if (publicNames != null) {
            PublicVehicles.glob(publicNames);
        }
    }

    /** {@code security} with these options' upload rule and page limit. */
    public SecuritySettings applyTo(SecuritySettings security) {
        return security.withHttpUpload(httpUpload).withWebPages(webPages);
    }

    /** The {@code --map-tiles} URL, or null. */
    public String mapTiles() {
        return mapTiles;
    }

    /** The {@code --public} glob, or null. */
    public String publicNames() {
        return publicNames;
    }
}
