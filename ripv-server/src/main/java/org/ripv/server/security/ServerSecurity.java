package org.ripv.server.security;

import java.util.concurrent.ScheduledExecutorService;
import java.util.function.Supplier;
import org.ripv.server.permit.PermitFile;

/** The server's defences, built from its settings; one per running server. */
public final class ServerSecurity implements AutoCloseable {
    private final ConnectionGate gate;
    private final LoginThrottle throttle;
    private final LoginPool pool;
    private final Logins logins;
    private final ServiceChallenges challenges;
    private final WebLogins web;

    public ServerSecurity(SecuritySettings settings, int maxClients, ScheduledExecutorService timer,
                          Supplier<PermitFile> permits, Supplier<String> secret) {
        this.throttle = new LoginThrottle(settings.throttle());
        this.gate = new ConnectionGate(ConnectionGate.Limits.defaults().withLoginDeadline(settings.loginDeadline())
                .withPerAddress(settings.pendingPerAddress()).withMaxLoggedIn(maxClients), timer, throttle);
        this.pool = new LoginPool();
        this.logins = new Logins(permits, throttle, pool, gate);
        this.challenges = new ServiceChallenges(secret);
        this.web = new WebLogins(logins, permits);
    }

    public ConnectionGate gate() {
        return gate;
    }

    public LoginThrottle throttle() {
        return throttle;
    }

    public Logins logins() {
        return logins;
    }

    /** The landing page's log-in, for {@code --http-upload}. */
    public WebLogins webAccess() {
        return web;
    }

    public ServiceChallenges challenges() {
        return challenges;
    }

    @Override
    public void close() {
        logins.close();
        pool.close();
    }
}
