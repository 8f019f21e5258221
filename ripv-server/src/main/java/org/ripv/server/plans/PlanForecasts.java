package org.ripv.server.plans;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.TableResult;
import org.ripv.plans.BehaviorFileReader;
import org.ripv.plans.Forecast;
import org.ripv.plans.PlanCheck;
import org.ripv.plans.PlanLimits;
import org.ripv.plans.Waypoint;

/**
 * {@code ?plan MAILBOX current} and {@code ?plan MAILBOX forecast FILE [SPEED]}: where the glider
 * is steering as far as the shore knows, and when it would reach each waypoint of a goto list
 * from its last fix.
 */
record PlanForecasts(ChangeBook book, Fixes fixes, PlanFiles files, PlanLimits limits) {
    /** A Slocum's usual horizontal speed through the water, for a glider with fewer than two fixes. */
    static final double ASSUMED_SPEED = 0.3;

    /**
     * The goto list the glider runs as far as the shore knows: of the goto file in effect (the
     * newest change shown in effect) and the newest {@code goto_l*.ma} fetched from it, the later;
     * with the waypoint its last dialog steered for and its last fix.
     */
    OutgoingServerMessage current(IncomingServerMessage request, String mailbox) throws IOException {
        List<String[]> rows = new ArrayList<>();
        StringBuilder b = new StringBuilder();
        Change inEffect = null;
        for (Change c : book.of(mailbox)) {
            if (c.kind() == Change.Kind.FILE && c.state() == Change.State.IN_EFFECT && !c.waypoints().isEmpty()) {
                inEffect = c;
            }
        }
        Path fetched = files.newestGotoFile(mailbox);
        long fetchedAt = fetched == null ? 0 : Files.getLastModifiedTime(fetched).toMillis();
        if (fetched != null && (inEffect == null || fetchedAt > inEffect.settledAt())) {
            PlanCheck c;
            try (InputStream in = Files.newInputStream(fetched)) {
                c = BehaviorFileReader.check(fetched.getFileName().toString(), in, limits);
            }
            if (c.ok()) {
                b.append("goto list: ").append(fetched.getFileName()).append(", fetched from the vehicle at ")
                        .append(Instant.ofEpochMilli(fetchedAt)).append('\n');
                for (Waypoint wp : c.file().waypoints()) {
                    rows.add(row("waypoint", Integer.toString(wp.n()), wp.lat(), wp.lon(), wp.comment()));
                }
            } else {
                b.append("goto list: ").append(fetched.getFileName()).append(", fetched, does not pass the check (?plan ")
                        .append(mailbox).append(" check ").append(fetched.getFileName()).append(")\n");
            }
        }
        if (rows.isEmpty() && inEffect != null) {
            b.append("goto list: ").append(inEffect.target()).append(", change ").append(inEffect.id()).append(", in effect since ")
                    .append(Instant.ofEpochMilli(inEffect.settledAt())).append('\n');
            for (int i = 0; i < inEffect.waypoints().size(); i++) {
                double[] w = inEffect.waypoints().get(i);
                rows.add(row("waypoint", Integer.toString(i), w[0], w[1], ""));
            }
        }
        if (rows.isEmpty() && b.length() == 0) {
            b.append("goto list: none known (no goto_l*.ma fetched from the vehicle, no goto file in effect)\n");
        }
        fixes.heading(mailbox).ifPresentOrElse(h -> {
            rows.add(row("heading", "", h.lat(), h.lon(), "c_wpt_lat/lon of the dialog at " + Instant.ofEpochMilli(h.time())));
            b.append(String.format(Locale.ROOT, "heading for %.5f, %.5f (c_wpt_lat/lon of the dialog at %s)%n", h.lat(), h.lon(),
                    Instant.ofEpochMilli(h.time())));
        }, () -> b.append("heading for: no c_wpt_lat/lon in a dialog since the server started\n"));
        fixes.last(mailbox).ifPresent(fx -> {
            rows.add(row("fix", "", fx.lat(), fx.lon(), Instant.ofEpochMilli(fx.time()).toString()));
            b.append(String.format(Locale.ROOT, "last fix %.5f, %.5f at %s%n", fx.lat(), fx.lon(), Instant.ofEpochMilli(fx.time())));
        });
        return PlanCommands.ok(request, Ids.FID_PLAN, b.toString().strip(), new TableResult("?plan current", List.of("kind", "n", "lat", "lon",
                "comment"), List.of("VARCHAR", "VARCHAR", "DOUBLE", "DOUBLE", "VARCHAR"), rows, false));
    }

    private static String[] row(String kind, String n, double lat, double lon, String comment) {
        return new String[] {kind, n, String.format(Locale.ROOT, "%.5f", lat), String.format(Locale.ROOT, "%.5f", lon), comment};
    }

    /**
     * Distance, bearing and ETA to each waypoint from the vehicle's last fix. The speed through
     * the water is the pilot's, else the last two fixes' speed over ground less the current, else
     * {@value #ASSUMED_SPEED} m/s; the current is the last dialog's {@code m_water_vx/vy}.
     */
    OutgoingServerMessage forecast(IncomingServerMessage request, String mailbox, String name, String speedText)
            throws IOException {
        PlanFiles.Found f = files.find(mailbox, name);
        PlanCheck c = files.read(f, name);
        if (!c.ok()) {
            return PlanCommands.error(request, Ids.FID_PLAN, ErrorCode.BAD_REQUEST, PlanFiles.refusal(c, f));
        }
        if (!c.file().isGoto()) {
            throw new IllegalArgumentException(name + " is a " + c.file().behavior() + " file: only a goto list has waypoints to forecast");
        }
        Fixes.Fix fix = fixes.last(mailbox).orElseThrow(() -> new IllegalArgumentException("no GPS fix of " + mailbox
                + " since the server started: a forecast starts from the last surfacing's position"));
        Fixes.Current cur = fixes.current(mailbox).orElse(new Fixes.Current(0, 0));
        String currentWhy = fixes.current(mailbox).isPresent()
                ? String.format(Locale.ROOT, "depth-averaged current %.3f m/s east, %.3f m/s north (the last dialog's m_water_vx/vy)",
                cur.east(), cur.north()) : "no current known (m_water_vx/vy not in the dialogs)";
        double speed;
        String speedWhy;
        if (speedText != null) {
            if (!PlanCommands.NUMBER.matcher(speedText).matches() || !(Double.parseDouble(speedText) > 0) || Double.parseDouble(speedText) > 5) {
                throw new IllegalArgumentException("SPEED is the glider's speed through the water in m/s, over 0 and at most 5, not '"
                        + speedText + "'");
            }
            speed = Double.parseDouble(speedText);
            speedWhy = "speed " + speedText + " m/s (given)";
        } else {
            Fixes.Fix before = fixes.previous(mailbox).orElse(null);
            double seconds = before == null ? 0 : (fix.time() - before.time()) / 1000.0;
            if (before != null && seconds >= 60) {
                double d = Forecast.distance(before.lat(), before.lon(), fix.lat(), fix.lon());
                double b = Math.toRadians(Forecast.bearing(before.lat(), before.lon(), fix.lat(), fix.lon()));
                double east = d / seconds * Math.sin(b) - cur.east();
                double north = d / seconds * Math.cos(b) - cur.north();
                speed = Math.hypot(east, north);
                speedWhy = String.format(Locale.ROOT, "speed %.3f m/s through the water (%.3f m/s over ground between the last two"
                        + " fixes, less the current)", speed, d / seconds);
            } else {
                speed = 0;
                speedWhy = "";
            }
            if (!(speed > 0.05)) {
                speed = ASSUMED_SPEED;
                speedWhy = "speed " + ASSUMED_SPEED + " m/s (assumed: fewer than two fixes a minute apart, or no way made)";
            }
        }
        List<Forecast.Leg> legs = Forecast.legs(c.file(), fix.lat(), fix.lon(),
                Instant.ofEpochMilli(fix.time()), speed, cur.east(), cur.north());
        String basis = String.format(Locale.ROOT, "of %s for %s from its fix at %s (%.5f, %.5f); %s; %s", name, mailbox,
                Instant.ofEpochMilli(fix.time()), fix.lat(), fix.lon(), speedWhy, currentWhy);
        List<String[]> rows = new ArrayList<>();
        for (Forecast.Leg l : legs) {
            rows.add(new String[] {Integer.toString(l.n()), String.format(Locale.ROOT, "%.5f", l.lat()),
                    String.format(Locale.ROOT, "%.5f", l.lon()), String.format(Locale.ROOT, "%.1f", l.legMetres()),
                    String.format(Locale.ROOT, "%.1f", l.bearing()), String.format(Locale.ROOT, "%.1f", l.totalMetres()),
                    l.eta() == null ? null : l.eta().toString()});
        }
        return PlanCommands.ok(request, Ids.FID_PLAN, Forecast.render(legs, basis), new TableResult("?plan forecast " + name,
                List.of("n", "lat", "lon", "leg_m", "bearing", "total_m", "eta"),
                List.of("INTEGER", "DOUBLE", "DOUBLE", "DOUBLE", "DOUBLE", "DOUBLE", "VARCHAR"), rows, false));
    }
}
