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
 */
public record SecuritySettings(Duration loginDeadline, int pendingPerAddress, LoginThrottle.Policy throttle,
                               boolean plain, boolean httpUpload) {

    public static SecuritySettings defaults() {
        return new SecuritySettings(Duration.ofSeconds(10), 16, LoginThrottle.Policy.defaults(), false, false);
    }

    public SecuritySettings withLoginDeadline(Duration d) {
        return new SecuritySettings(d, pendingPerAddress, throttle, plain, httpUpload);
    }

    public SecuritySettings withPendingPerAddress(int n) {
        return new SecuritySettings(loginDeadline, n, throttle, plain, httpUpload);
    }

    public SecuritySettings withThrottle(LoginThrottle.Policy p) {
        return new SecuritySettings(loginDeadline, pendingPerAddress, p, plain, httpUpload);
    }

    public SecuritySettings withPlain(boolean b) {
        return new SecuritySettings(loginDeadline, pendingPerAddress, throttle, b, httpUpload);
    }

    public SecuritySettings withHttpUpload(boolean b) {
        return new SecuritySettings(loginDeadline, pendingPerAddress, throttle, plain, b);
    }
}
