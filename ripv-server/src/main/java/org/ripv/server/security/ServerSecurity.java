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

    public ServerSecurity(SecuritySettings settings, int maxClients, ScheduledExecutorService timer,
                          Supplier<PermitFile> permits, Supplier<String> secret) {
        this.gate = new ConnectionGate(ConnectionGate.Limits.defaults().withLoginDeadline(settings.loginDeadline())
                .withPerAddress(settings.pendingPerAddress()).withMaxLoggedIn(maxClients), timer);
        this.throttle = new LoginThrottle(settings.throttle());
        this.pool = new LoginPool();
        this.logins = new Logins(permits, throttle, pool, gate);
        this.challenges = new ServiceChallenges(secret);
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

    public ServiceChallenges challenges() {
        return challenges;
    }

    @Override
    public void close() {
        pool.close();
    }
}
