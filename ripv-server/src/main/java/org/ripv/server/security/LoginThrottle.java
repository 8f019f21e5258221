package org.ripv.server.security;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.LongSupplier;

/**
 * Failed log-ins counted per user name and per source address, across connections. After a few
 * free failures each further one blocks the name (or the address) for twice as long as the last,
 * from {@code firstDelay} up to {@code lock}; a block that reached {@code lock} is the temporary
 * lock an admin lifts with {@code ?unlock-login}. While blocked, a log-in is refused at once,
 * without hashing the password, so a flood costs the server almost nothing.
 */
public final class LoginThrottle {

    /**
     * @param freePerUser    failures a user name may have before back-off starts (default 5)
     * @param freePerAddress failures a source address may have before back-off starts (default 10)
     * @param firstDelay     the first block (default 1 s); each further failure doubles it
     * @param lock           the longest block: the temporary lock (default 15 min)
     */
    public record Policy(int freePerUser, int freePerAddress, Duration firstDelay, Duration lock) {
        public static Policy defaults() {
            return new Policy(5, 10, Duration.ofSeconds(1), Duration.ofMinutes(15));
        }
    }

    /** Why a log-in is refused without trying the password: who is blocked and for how long. */
    public record Block(String who, Duration left, boolean locked) {}

    private static final class State {
        int failures;
        long blockedUntil;
        long last;
    }

    private static final int MAX_ENTRIES = 100_000;

    private final Policy policy;
    private final LongSupplier clock;
    private final Map<String, State> states = new HashMap<>();

    public LoginThrottle(Policy policy) {
        this(policy, System::currentTimeMillis);
    }

    LoginThrottle(Policy policy, LongSupplier clock) {
        this.policy = policy;
        this.clock = clock;
    }

    /** The block in force for this user or address, or null when a log-in may be tried. */
    public synchronized Block blocked(String user, String address) {
        long now = clock.getAsLong();
        Block a = block("address " + address, states.get(addressKey(address)), now);
        Block u = block("user " + user, states.get(userKey(user)), now);
        if (a == null) {
            return u;
        }
        return u == null || a.left().compareTo(u.left()) >= 0 ? a : u;
    }

    /** The block in force for this address alone, or null: checked at accept, before any TLS handshake. */
    public synchronized Block addressBlocked(String address) {
        return block("address " + address, states.get(addressKey(address)), clock.getAsLong());
    }

    private Block block(String who, State s, long now) {
        if (s == null || s.blockedUntil <= now) {
            return null;
        }
        long left = s.blockedUntil - now;
        return new Block(who, Duration.ofMillis(left), isLock(s));
    }

    private boolean isLock(State s) {
        return s.blockedUntil - s.last >= policy.lock().toMillis();
    }

    /** Counts a failure for both; returns the block it caused, or null. */
    public synchronized Block failure(String user, String address) {
        long now = clock.getAsLong();
        if (states.size() > MAX_ENTRIES) {
            prune(now);
        }
        fail(states.computeIfAbsent(userKey(user), k -> new State()), policy.freePerUser(), now);
        fail(states.computeIfAbsent(addressKey(address), k -> new State()), policy.freePerAddress(), now);
        return blocked(user, address);
    }

    /**
     * A log-in refused because its user name is blocked: a failure of the address alone. Someone
     * who keeps trying a blocked name from one address soon has the address blocked, and is then
     * refused at connect, before any TLS handshake ({@link ConnectionGate}). Returns the address's
     * block, or null.
     */
    public synchronized Block refusedWhileBlocked(String address) {
        long now = clock.getAsLong();
        if (states.size() > MAX_ENTRIES) {
            prune(now);
        }
        fail(states.computeIfAbsent(addressKey(address), k -> new State()), policy.freePerAddress(), now);
        return addressBlocked(address);
    }

    private void fail(State s, int free, long now) {
        if (s.last != 0 && now - s.last > policy.lock().toMillis() && s.blockedUntil <= now) {
            s.failures = 0; // quiet for a lock's length: start afresh
        }
        s.failures++;
        s.last = now;
        int over = s.failures - free;
        if (over > 0) {
            long delay = policy.firstDelay().toMillis() << Math.min(over - 1, 30);
            s.blockedUntil = now + Math.min(delay, policy.lock().toMillis());
        }
    }

    /** A good log-in clears the user's failures (not the address's: one valid account must not reset it). */
    public synchronized void success(String user) {
        states.remove(userKey(user));
    }

    /** Lifts the block of a user name or an address; true when there was anything to lift. */
    public synchronized boolean lift(String who) {
        boolean u = states.remove(userKey(who)) != null;
        boolean a = states.remove(addressKey(who)) != null;
        return u || a;
    }

    /** One line per user or address with failures: what {@code ?logins} shows. */
    public synchronized List<String> describe() {
        long now = clock.getAsLong();
        prune(now);
        List<String> out = new ArrayList<>();
        states.entrySet().stream().sorted(Map.Entry.comparingByKey()).forEach(e -> {
            State s = e.getValue();
            String state = s.blockedUntil > now
                    ? (isLock(s) ? "LOCKED" : "blocked") + " until " + Instant.ofEpochMilli(s.blockedUntil)
                    : "not blocked";
            out.add(e.getKey() + "  " + s.failures + " failure(s), last " + Instant.ofEpochMilli(s.last) + ", " + state);
        });
        return out;
    }

    private void prune(long now) {
        states.values().removeIf(s -> s.blockedUntil <= now && now - s.last > policy.lock().toMillis());
    }

    private static String userKey(String user) {
        return "user " + user;
    }

    private static String addressKey(String address) {
        return "address " + address;
    }
}
