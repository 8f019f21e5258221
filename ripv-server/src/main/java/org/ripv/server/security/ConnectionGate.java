package org.ripv.server.security;

import java.net.InetAddress;
import java.time.Duration;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * Who may hold a connection to the client port. A connection that has not logged in is
 * <em>pending</em>: it must log in within the deadline or is closed, and one source address may
 * hold only so many pending connections. The client cap counts logged-in clients only, so
 * connections that never log in cannot lock anybody out (issue 10, item 3).
 */
public final class ConnectionGate {

    /**
     * @param loginDeadline how long a connection may stay without logging in (default 10 s)
     * @param perAddress    pending connections one source address may hold (default 16)
     * @param maxPending    pending connections in all (default 4,096), a bound on threads
     * @param maxLoggedIn   logged-in clients at once (the client cap, default 1,000)
     */
    public record Limits(Duration loginDeadline, int perAddress, int maxPending, int maxLoggedIn) {
        public static Limits defaults() {
            return new Limits(Duration.ofSeconds(10), 16, 4096, 1000);
        }

        public Limits withLoginDeadline(Duration d) {
            return new Limits(d, perAddress, maxPending, maxLoggedIn);
        }

        public Limits withPerAddress(int n) {
            return new Limits(loginDeadline, n, maxPending, maxLoggedIn);
        }

        public Limits withMaxLoggedIn(int n) {
            return new Limits(loginDeadline, perAddress, maxPending, n);
        }
    }

    /**
     * A connection not logged in yet, with {@code leftNanos} of its time to log in left when its
     * deadline was last set; {@code deadline} is null while its {@code ?login} is being checked.
     */
    private record Pending(InetAddress address, Runnable expire, ScheduledFuture<?> deadline, long setAt, long leftNanos) {
        long leftNow() {
            return Math.max(0, leftNanos - (System.nanoTime() - setAt));
        }
    }

    private final Limits limits;
    private final ScheduledExecutorService timer;
    private final Map<String, Pending> pending = new HashMap<>();
    private final Map<InetAddress, Integer> pendingPerAddress = new HashMap<>();
    private final Set<String> loggedIn = new HashSet<>();
    private final LoginThrottle throttle;

    /** @param throttle an address it blocks is refused at accept, before any TLS handshake or hashing */
    public ConnectionGate(Limits limits, ScheduledExecutorService timer, LoginThrottle throttle) {
        this.limits = limits;
        this.timer = timer;
        this.throttle = throttle;
    }

    public Limits limits() {
        return limits;
    }

    /**
     * A new connection: admitted (and {@code expire} closes it at the deadline unless it logged in
     * by then), or refused; both the refusal and the expiry are audit lines.
     *
     * @return false when refused: the caller closes the socket
     */
    public boolean admit(String clientId, InetAddress address, Runnable expire) {
        String from = address.getHostAddress();
        LoginThrottle.Block blocked = throttle.addressBlocked(from);
        if (blocked != null) {
            Audit.limited("blocked " + from, "connection-refused", "from", from, "reason", "address-blocked",
                    "seconds-left", Math.max(1, blocked.left().toSeconds()));
            return false;
        }
        String refused = tryAdmit(clientId, address, () -> {
            Audit.log(true, "login-deadline", "from", from, "client", clientId);
            expire.run();
        });
        if (refused != null) {
            Audit.limited("pending " + from, "connection-refused", "from", from, "reason", refused);
        }
        return refused == null;
    }

    private synchronized String tryAdmit(String clientId, InetAddress address, Runnable expire) {
        int fromHere = pendingPerAddress.getOrDefault(address, 0);
        if (fromHere >= limits.perAddress()) {
            return fromHere + " connections from " + address.getHostAddress() + " have not logged in yet";
        }
        if (pending.size() >= limits.maxPending()) {
            return pending.size() + " connections have not logged in yet";
        }
        long left = limits.loginDeadline().toNanos();
        pending.put(clientId, new Pending(address, expire, deadline(clientId, expire, left), System.nanoTime(), left));
        pendingPerAddress.merge(address, 1, Integer::sum);
        return null;
    }

    private ScheduledFuture<?> deadline(String clientId, Runnable expire, long nanos) {
        return timer.schedule(() -> {
            if (isPending(clientId)) {
                expire.run();
            }
        }, nanos, TimeUnit.NANOSECONDS);
    }

    /**
     * The connection's {@code ?login} arrived and waits for its check: its deadline stops. On a
     * loaded machine the PBKDF2 checks queued before it, and its own, could take the rest of a
     * client's time, and the server closed a connection that had sent the right password in time.
     */
    public synchronized void checking(String clientId) {
        Pending p = pending.get(clientId);
        if (p != null && p.deadline() != null) {
            p.deadline().cancel(false);
            pending.put(clientId, new Pending(p.address(), p.expire(), null, System.nanoTime(), p.leftNow()));
        }
    }

    /**
     * The check ended. Still not logged in (refused): the deadline goes on with the time that was
     * left when the check began, so a connection that never logs in holds its place no longer than
     * the deadline of its own time, however many checks it asked for.
     */
    public synchronized void checked(String clientId) {
        Pending p = pending.get(clientId);
        if (p != null && p.deadline() == null) {
            long left = p.leftNanos();
            pending.put(clientId, new Pending(p.address(), p.expire(), deadline(clientId, p.expire(), left), System.nanoTime(), left));
        }
    }

    /** Pending and not being checked. */
    private synchronized boolean isPending(String clientId) {
        Pending p = pending.get(clientId);
        return p != null && p.deadline() != null;
    }

    /**
     * The connection logged in: it is no longer pending.
     *
     * @return false when the client cap is reached (the caller refuses the log-in and closes)
     */
    public synchronized boolean loggedIn(String clientId) {
        if (!loggedIn.contains(clientId) && loggedIn.size() >= limits.maxLoggedIn()) {
            return false;
        }
        release(clientId);
        loggedIn.add(clientId);
        return true;
    }

    /** The connection closed, logged in or not. */
    public synchronized void closed(String clientId) {
        release(clientId);
        loggedIn.remove(clientId);
    }

    private void release(String clientId) {
        Pending p = pending.remove(clientId);
        if (p != null) {
            if (p.deadline() != null) {
                p.deadline().cancel(false);
            }
            pendingPerAddress.computeIfPresent(p.address(), (a, n) -> n <= 1 ? null : n - 1);
        }
    }

    public synchronized int pendingCount() {
        return pending.size();
    }

    public synchronized int loggedInCount() {
        return loggedIn.size();
    }
}
