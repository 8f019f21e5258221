package org.ripv.server;

/** Starts the HTTP landing page beside a server, when one is configured. */
final class LandingPages {
    private LandingPages() {}

    static void start(RIPVServer server, ServerConfig config) {
        // Wired to org.ripv.server.http.LandingPage when it lands (issue 6).
    }
}
