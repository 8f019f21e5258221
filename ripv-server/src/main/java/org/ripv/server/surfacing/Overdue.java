package org.ripv.server.surfacing;

import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Function;
import org.ripv.surfacing.CallOutlook;

/**
 * Which vehicles are late: each call's start is noted; a vehicle not on a call whose last call
 * began longer ago than its expected interval plus a grace is overdue, once, until it calls again.
 * The interval is the link's {@code overdue=}, the vehicle's {@code overdue} rule, or what its
 * calls taught ({@link CallOutlook#learned}). A vehicle's calls before the server started are
 * its stored call records' times ({@link #seed}), so a restart forgets nothing it learned. The
 * worker thread of {@link Surfacings} drives it; {@link #expected} answers commands.
 */
final class Overdue {
    static final int LEARN_FROM = CallOutlook.LEARN_FROM;

    /** A vehicle that is late now, or that called after being late. */
    record Late(String mailbox, String text) {}

    /** The interval a vehicle is expected to call at, and what it comes from, in words. */
    record Expected(Duration every, String from) {}

    private static final class Calls {
        final ArrayDeque<Long> starts = new ArrayDeque<>();
        /** The link's {@code overdue=} as its SURFACED announced it, or null. */
        Duration announced;
        boolean onCall;
        boolean late;
        long due;
    }

    private final Map<String, Calls> vehicles = new HashMap<>();
    private final Function<String, AlertRules.Thresholds> thresholds;

    Overdue(Function<String, AlertRules.Thresholds> thresholds) {
        this.thresholds = thresholds;
    }

    /**
     * A call began at {@code time}; {@code announced} is the link's interval its SURFACED gave (or
     * null). Returns the text to publish when it was overdue, else null.
     */
    synchronized String called(String mailbox, long time, Duration announced) {
        Calls c = vehicles.computeIfAbsent(mailbox, k -> new Calls());
        c.announced = announced;
        String back = null;
        if (c.late) {
            back = "called again " + words(Duration.ofMillis(Math.max(0, time - c.due))) + " after it was due";
        }
        c.late = false;
        c.onCall = true;
        c.starts.addLast(time);
        if (c.starts.size() > LEARN_FROM + 1) {
            c.starts.removeFirst();
        }
        return back;
    }

    /** The call ended (dived, or lost). */
    synchronized void ended(String mailbox) {
        Calls c = vehicles.get(mailbox);
        if (c != null) {
            c.onCall = false;
        }
    }

    /** Vehicles that have become late by {@code now}. */
    synchronized List<Late> check(long now) {
        List<Late> out = new ArrayList<>();
        vehicles.forEach((mailbox, c) -> {
            if (c.onCall || c.late || c.starts.isEmpty()) {
                return;
            }
            AlertRules.Thresholds t = thresholds.apply(mailbox);
            Duration every = interval(c, t);
            if (every == null) {
                return;
            }
            c.due = c.starts.getLast() + every.toMillis() + t.grace().toMillis();
            if (now >= c.due) {
                c.late = true;
                out.add(new Late(mailbox, "no call for " + words(Duration.ofMillis(now - c.starts.getLast()))
                        + "; expected every " + words(every) + " (" + from(c, t) + ") + " + words(t.grace()) + " grace"));
            }
        });
        return out;
    }

    /** How long the worker may wait before a vehicle could become late (at most a minute). */
    synchronized long waitMillis(long now) {
        long soonest = now + 60_000;
        for (Map.Entry<String, Calls> e : vehicles.entrySet()) {
            Calls c = e.getValue();
            if (c.onCall || c.late || c.starts.isEmpty()) {
                continue;
            }
            AlertRules.Thresholds t = thresholds.apply(e.getKey());
            Duration every = interval(c, t);
            if (every != null) {
                soonest = Math.min(soonest, c.starts.getLast() + every.toMillis() + t.grace().toMillis());
            }
        }
        return Math.max(1, soonest - now);
    }

    /** The link's {@code overdue=}, else the rules file's, else what its calls taught. */
    private static Duration interval(Calls c, AlertRules.Thresholds t) {
        return c.announced != null ? c.announced : t.overdue() != null ? t.overdue() : CallOutlook.learned(List.copyOf(c.starts));
    }

    private static String from(Calls c, AlertRules.Thresholds t) {
        return c.announced != null ? "its link's overdue=" : t.overdue() != null ? "its overdue rule"
                : "learned from its last " + (c.starts.size() - 1) + " intervals";
    }

    /**
     * The calls a vehicle made before the server started (its call records' start times, oldest
     * first), so its interval is known at once. A vehicle already due before {@code now} was told
     * OVERDUE by the server that ran then: it is not told again until it has called.
     */
    synchronized void seed(String mailbox, List<Long> starts, long now) {
        if (starts.isEmpty() || vehicles.containsKey(mailbox)) {
            return;
        }
        Calls c = new Calls();
        starts.subList(Math.max(0, starts.size() - LEARN_FROM - 1), starts.size()).forEach(c.starts::addLast);
        AlertRules.Thresholds t = thresholds.apply(mailbox);
        Duration every = interval(c, t);
        if (every != null) {
            c.due = c.starts.getLast() + every.toMillis() + t.grace().toMillis();
            c.late = c.due <= now;
        }
        vehicles.put(mailbox, c);
    }

    /** Whether the vehicle's calls are known here (seeded or seen since the start). */
    synchronized boolean knows(String mailbox) {
        return vehicles.containsKey(mailbox);
    }

    /** The interval the vehicle is expected to call at now, or null when nothing sets or taught one. */
    synchronized Expected expected(String mailbox) {
        Calls c = vehicles.get(mailbox);
        AlertRules.Thresholds t = thresholds.apply(mailbox);
        if (c == null) {
            return t.overdue() == null ? null : new Expected(t.overdue(), "its overdue rule");
        }
        Duration every = interval(c, t);
        return every == null ? null : new Expected(every, from(c, t));
    }

    static String words(Duration d) {
        long s = d.toSeconds();
        if (s < 120) {
            return s + " s";
        }
        if (s < 7200) {
            return s / 60 + " min";
        }
        return String.format(Locale.ROOT, "%d h %02d min", s / 3600, s / 60 % 60);
    }
}
