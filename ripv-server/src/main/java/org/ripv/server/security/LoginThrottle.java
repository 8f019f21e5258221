package org.ripv.server.security;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.LongSupplier;

/**
 * Failed log-ins counted per source address, per user name from each address, and per user name,
 * across connections. After a few free failures each further one blocks for twice as long as the
 * last, from {@code firstDelay}: the guessing source — an address, or a user name from one address
 * — up to {@code lock}, the temporary lock an admin lifts with {@code ?unlock-login}; the user
 * name from everywhere up to {@code userMax} only (seconds), and never from an address it logged
 * in from before. So guesses spread over many addresses are slowed, yet they cannot lock the real
 * user out (issue 23, item 15: twelve wrong passwords from twelve addresses locked the user
 * everywhere for minutes). While blocked, a log-in is refused at once, without hashing the
 * password, so a flood costs the server almost nothing.
 */
public final class LoginThrottle {

    /**
     * @param freePerUser    failures a user name may have before back-off starts (default 5)
     * @param freePerAddress failures a source address may have before back-off starts (default 10)
     * @param firstDelay     the first block (default 1 s); each further failure doubles it
     * @param lock           the longest block of a source: the temporary lock (default 15 min)
     * @param userMax        the longest block of a user name from addresses it has not logged in
     *                       from (default 8 s): it slows guessing, and never locks the user out
     */
    public record Policy(int freePerUser, int freePerAddress, Duration firstDelay, Duration lock, Duration userMax) {
        public static final Duration USER_MAX = Duration.ofSeconds(8);

        public Policy(int freePerUser, int freePerAddress, Duration firstDelay, Duration lock) {
            this(freePerUser, freePerAddress, firstDelay, lock, lock.compareTo(USER_MAX) < 0 ? lock : USER_MAX);
        }

        public static Policy defaults() {
            return new Policy(5, 10, Duration.ofSeconds(1), Duration.ofMinutes(15), USER_MAX);
        }
    }

    /** Why a log-in is refused without trying the password: who is blocked and for how long. */
    public record Block(String who, Duration left, boolean locked) {}

    private static final class State {
        int failures;
        long blockedUntil;
        long last;
        /** False for a user name from everywhere: its blocks stop at userMax and are never a lock. */
        boolean lockable = true;
    }

    private static final int MAX_ENTRIES = 100_000;
    /** Addresses remembered per user as "logged in from here before", newest last. */
    private static final int KNOWN_PER_USER = 16;

    private final Policy policy;
    private final LongSupplier clock;
    private final Map<String, State> states = new HashMap<>();
    private final Map<String, LinkedHashSet<String>> known = new LinkedHashMap<>(16, 0.75f, true) {
        private static final long serialVersionUID = 1L;

        @Override
        protected boolean removeEldestEntry(Map.Entry<String, LinkedHashSet<String>> eldest) {
            return size() > MAX_ENTRIES;
        }
    };

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
        Block p = block("user " + user + " from " + address, states.get(pairKey(user, address)), now);
        Block u = isKnown(user, address) ? null : block("user " + user, states.get(userKey(user)), now);
        return longest(longest(a, p), u);
    }

    /**
     * As {@link #blocked}, for a log-in about to be tried: a user name past its free failures is
     * tried from an address it never logged in from at most once per {@code userMax} — this try
     * takes the turn — so guesses spread over many addresses cost the server one password hash
     * per user every few seconds, not one per address.
     */
    public synchronized Block admit(String user, String address) {
        Block b = blocked(user, address);
        if (b != null || isKnown(user, address)) {
            return b;
        }
        State u = states.get(userKey(user));
        long now = clock.getAsLong();
        if (u != null && u.failures >= policy.freePerUser() && now - u.last <= policy.lock().toMillis()) {
            u.blockedUntil = Math.max(u.blockedUntil, now + policy.userMax().toMillis());
        }
        return null;
    }

    private static Block longest(Block a, Block b) {
        if (a == null) {
            return b;
        }
        return b == null || a.left().compareTo(b.left()) >= 0 ? a : b;
    }

    private boolean isKnown(String user, String address) {
        Set<String> k = known.get(user);
        return k != null && k.contains(address);
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
        return s.lockable && s.blockedUntil - s.last >= policy.lock().toMillis();
    }

    /** Counts a failure for both; returns the block it caused, or null. */
    public synchronized Block failure(String user, String address) {
        long now = clock.getAsLong();
        if (states.size() > MAX_ENTRIES) {
            prune(now);
        }
        State u = states.computeIfAbsent(userKey(user), k -> new State());
        u.lockable = false;
        fail(u, policy.freePerUser(), now);
        fail(states.computeIfAbsent(pairKey(user, address), k -> new State()), policy.freePerUser(), now);
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
            long max = s.lockable ? policy.lock().toMillis() : policy.userMax().toMillis();
            s.blockedUntil = now + Math.min(delay, max);
        }
    }

    /**
     * A good log-in clears the user's failures (not the address's: one valid account must not
     * reset it) and remembers the address as one the user logs in from: blocks of the user name
     * alone do not apply there.
     */
    public synchronized void success(String user, String address) {
        states.remove(userKey(user));
        states.remove(pairKey(user, address));
        LinkedHashSet<String> k = known.computeIfAbsent(user, x -> new LinkedHashSet<>());
        k.remove(address);
        k.add(address);
        if (k.size() > KNOWN_PER_USER) {
            k.remove(k.iterator().next());
        }
    }

    /** Lifts the block of a user name or an address; true when there was anything to lift. */
    public synchronized boolean lift(String who) {
        boolean u = states.remove(userKey(who)) != null;
        boolean a = states.remove(addressKey(who)) != null;
        boolean p = states.keySet().removeIf(k -> k.startsWith("pair ") && (k.startsWith(pairKey(who, "")) || k.endsWith(" from " + who)));
        return u || a || p;
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

    private static String pairKey(String user, String address) {
        return "pair " + user + " from " + address;
    }

    private static String addressKey(String address) {
        return "address " + address;
    }
}
