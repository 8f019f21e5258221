package org.ripv.server.security;

import java.time.Duration;

/**
 * The server's security settings (docs/security.md).
 *
 * @param loginDeadline     how long a connection may stay without logging in (10 s)
 * @param pendingPerAddress connections not yet logged in that one source address may hold (16)
 * @param throttle          back-off and lock after failed log-ins
 * @param plain             true: no TLS on the client port and the landing page (a test lab only)
 * @param httpUpload        true: the landing page takes uploads from logged-in users (off by default)
 * @param webPages          web console pages (WebSockets) one user may have open, over all their log-ins; one log-in
 *                          at most half of it ({@code --web-pages}, default 64: issue 33 item 2)
 */
public record SecuritySettings(Duration loginDeadline, int pendingPerAddress, LoginThrottle.Policy throttle,
                               boolean plain, boolean httpUpload, int webPages) {
    public static final int DEFAULT_WEB_PAGES = 64;

    public SecuritySettings {
        if (webPages < 2) {
            throw new IllegalArgumentException("--web-pages must be at least 2, got " + webPages);
        }
    }

    public static SecuritySettings defaults() {
        return new SecuritySettings(Duration.ofSeconds(10), 16, LoginThrottle.Policy.defaults(), false, false, DEFAULT_WEB_PAGES);
    }

    public SecuritySettings withLoginDeadline(Duration d) {
        return new SecuritySettings(d, pendingPerAddress, throttle, plain, httpUpload, webPages);
    }

    public SecuritySettings withPendingPerAddress(int n) {
        return new SecuritySettings(loginDeadline, n, throttle, plain, httpUpload, webPages);
    }

    public SecuritySettings withThrottle(LoginThrottle.Policy p) {
        return new SecuritySettings(loginDeadline, pendingPerAddress, p, plain, httpUpload, webPages);
    }

    public SecuritySettings withPlain(boolean b) {
        return new SecuritySettings(loginDeadline, pendingPerAddress, throttle, b, httpUpload, webPages);
    }

    public SecuritySettings withHttpUpload(boolean b) {
        return new SecuritySettings(loginDeadline, pendingPerAddress, throttle, plain, b, webPages);
    }

    public SecuritySettings withWebPages(int n) {
        return new SecuritySettings(loginDeadline, pendingPerAddress, throttle, plain, httpUpload, n);
    }
}
