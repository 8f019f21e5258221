package org.ripv.plans;

import java.util.Locale;

/**
 * A checked file as text for people: a summary line, the waypoints ({@code n}, {@code lat},
 * {@code lon} in decimal degrees, {@code comment}) and the b_args. The same text answers
 * {@code ripv plan check} and the server's {@code ?plan MAILBOX check}.
 */
public final class PlanTable {
    private PlanTable() {
    }

    public static String summary(BehaviorFile f) {
        return f.name() + ": " + f.behavior() + (f.isGoto() ? ", " + f.waypoints().size() + " waypoint(s)" : "")
                + ", " + f.bargs().size() + " b_arg(s), sha256 " + f.sha256();
    }

    public static String render(BehaviorFile f) {
        StringBuilder b = new StringBuilder(summary(f));
        if (f.isGoto()) {
            b.append(String.format(Locale.ROOT, "%n%4s  %10s  %11s  %s", "n", "lat", "lon", "comment"));
            for (Waypoint w : f.waypoints()) {
                b.append(String.format(Locale.ROOT, "%n%4d  %10.5f  %11.5f  %s", w.n(), w.lat(), w.lon(), w.comment()).stripTrailing());
            }
        }
        b.append(String.format("%nb_args:"));
        int width = f.bargs().stream().mapToInt(a -> a.name().length() + a.units().length() + 2).max().orElse(0);
        for (BArg a : f.bargs()) {
            String decl = a.name() + "(" + a.units() + ")";
            b.append(String.format(Locale.ROOT, "%n  %-" + width + "s  %s%s", decl, a.text(),
                    a.comment().isEmpty() ? "" : "  # " + a.comment()));
        }
        return b.toString();
    }
}
