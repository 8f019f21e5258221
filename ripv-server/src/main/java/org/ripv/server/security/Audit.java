package org.ripv.server.security;

import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One line per security event on the logger {@code ripv.audit}, as {@code event key=value ...}
 * so that grep and awk read it (docs/security.md, "Reading the audit lines"). Values are cut and
 * stripped of white space and control characters: a user name an attacker chose cannot forge a line.
 * Each line also goes to the audit trails added with {@link #addTrail} (the server's state store).
 */
public final class Audit {
    private static final Logger AUDIT = LoggerFactory.getLogger("ripv.audit");
    private static final List<Trail> TRAILS = new CopyOnWriteArrayList<>();

    /** Where audit lines are kept beyond the log; must not block (the store's {@code AuditTrail} queues). */
    public interface Trail {
        void record(boolean warn, String line);
    }

    /** Adds a trail until the returned handle is closed (a running server's store; one per server). */
    public static AutoCloseable addTrail(Trail t) {
        TRAILS.add(t);
        return () -> TRAILS.remove(t);
    }

    private Audit() {}

    /** Logs {@code event k1=v1 k2=v2 ...} at WARN (failures, refusals) or INFO (the rest). */
    public static void log(boolean warn, String event, Object... keyValues) {
        StringBuilder b = new StringBuilder(event);
        for (int i = 0; i + 1 < keyValues.length; i += 2) {
            b.append(' ').append(keyValues[i]).append('=').append(clean(String.valueOf(keyValues[i + 1])));
        }
        if (warn) {
            AUDIT.warn("{}", b);
        } else {
            AUDIT.info("{}", b);
        }
        String line = b.toString();
        TRAILS.forEach(t -> t.record(warn, line));
    }

    private static final Map<String, long[]> LIMITED = new ConcurrentHashMap<>();

    /**
     * As {@link #log} at WARN, but at most one line per {@code key} every 10 s, with how many were
     * left out ({@code repeated=N}): a flood must not become a flood of log lines.
     */
    public static void limited(String key, String event, Object... keyValues) {
        long now = System.currentTimeMillis();
        long[] state = LIMITED.computeIfAbsent(key, k -> new long[] {0, 0});
        long skipped;
        synchronized (state) {
            if (now - state[0] < 10_000) {
                state[1]++;
                return;
            }
            skipped = state[1];
            state[0] = now;
            state[1] = 0;
        }
        if (LIMITED.size() > 10_000) {
            LIMITED.clear();
        }
        Object[] kv = Arrays.copyOf(keyValues, keyValues.length + 2);
        kv[keyValues.length] = "repeated";
        kv[keyValues.length + 1] = skipped;
        log(true, event, kv);
    }

    static String clean(String s) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.length() && b.length() < 64; i++) {
            char c = s.charAt(i);
            b.append(c <= ' ' || c == 0x7f || (c >= 0x80 && c < 0xa0) || c == '=' ? '_' : c);
        }
        if (s.length() > 64) {
            b.append("...");
        }
        return b.length() == 0 ? "-" : b.toString();
    }
}
