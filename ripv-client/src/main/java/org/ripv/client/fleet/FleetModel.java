package org.ripv.client.fleet;

import java.time.Duration;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.SessionState;
import org.ripv.messages.TableResult;

/**
 * The Fleet view's rows: one per vehicle, from the newest fix per vehicle in the database's
 * {@code positions} view ({@link #LATEST_SQL}), the fleet's recent fixes for the small tracks
 * ({@link #RECENT_SQL}), and the vehicle MailBoxes of {@code ?mailboxes} (call state, and the
 * position of the last SURFACED event when the database has none newer). A MailBox and a
 * database vehicle are the same when the MailBox's handle is the vehicle's name (any case).
 * Plain data, no Swing.
 */
public final class FleetModel {
    /** The newest fix of every vehicle (a vehicle's gps and dead-reckoned fix of one time: both). */
    public static final String LATEST_SQL = "SELECT p.vehicle, p.time_utc, p.lat, p.lon, p.source FROM positions p"
            + " JOIN (SELECT vehicle, MAX(time_utc) AS newest FROM positions GROUP BY vehicle) m"
            + " ON p.vehicle = m.vehicle AND p.time_utc = m.newest";
    /** The fleet's newest fixes, for the tracks. */
    public static final String RECENT_SQL = "SELECT vehicle, time_utc, lat, lon FROM positions ORDER BY time_utc DESC"
            + " FETCH FIRST " + 5000 + " ROWS ONLY";
    /** At most this many points in a vehicle's small track. */
    public static final int TRACK_POINTS = 300;

    /**
     * One vehicle.
     *
     * @param name     the vehicle's name (database) or the MailBox's handle
     * @param mailbox  its MailBox's address, or "" when no MailBox has its name
     * @param state    the call state ("on call", "dived", "lost", "unknown"), or "" without a MailBox
     * @param fixTime  the last fix, epoch milliseconds, or 0 when none is known
     * @param lat      its latitude in decimal degrees, or NaN
     * @param lon      its longitude, or NaN
     * @param source   {@code gps}, {@code dead-reckoned}, or {@code console} (a SURFACED event's position)
     * @param trackLon the recent fixes' longitudes, oldest first
     * @param trackLat their latitudes
     */
    public record Vehicle(String name, String mailbox, String state, long fixTime, double lat, double lon, String source,
                          double[] trackLon, double[] trackLat) {
        public boolean hasFix() {
            return fixTime > 0 && !Double.isNaN(lat) && !Double.isNaN(lon);
        }
    }

    private List<Vehicle> vehicles = List.of();
    private String problem = "";

    /** The vehicles, by name. */
    public List<Vehicle> vehicles() {
        return vehicles;
    }

    /** Why the database part is missing ("no DatabaseServer", the query's error), or "". */
    public String problem() {
        return problem;
    }

    /**
     * Rebuilds the rows.
     *
     * @param mailboxes every service's MailBoxes ({@code ?mailboxes}); vehicle ones carry a session
     * @param latest    the answer to {@link #LATEST_SQL}, or null
     * @param recent    the answer to {@link #RECENT_SQL}, or null
     * @param problem   why the database answers are missing, or ""
     */
    public void update(List<MailboxStatus> mailboxes, TableResult latest, TableResult recent, String problem) {
        this.problem = problem == null ? "" : problem;
        Map<String, Vehicle> byName = new LinkedHashMap<>();
        Map<String, List<double[]>> tracks = new LinkedHashMap<>();
        if (recent != null) {
            Columns c = new Columns(recent);
            for (String[] row : recent.rows()) { // newest first
                String v = c.text(row, "vehicle");
                double lat = c.number(row, "lat");
                double lon = c.number(row, "lon");
                if (v != null && Double.isFinite(lat) && Double.isFinite(lon)) {
                    tracks.computeIfAbsent(key(v), k -> new ArrayList<>()).add(new double[] {lon, lat});
                }
            }
        }
        if (latest != null) {
            Columns c = new Columns(latest);
            for (String[] row : latest.rows()) {
                String v = c.text(row, "vehicle");
                if (v == null) {
                    continue;
                }
                String source = c.text(row, "source");
                Vehicle had = byName.get(key(v));
                if (had != null && !"dead-reckoned".equals(had.source())) {
                    continue; // one time, two fixes: the GPS one wins
                }
                byName.put(key(v), new Vehicle(v, "", "", time(c.text(row, "time_utc")), c.number(row, "lat"),
                        c.number(row, "lon"), source == null ? "" : source, null, null));
            }
        }
        for (MailboxStatus m : mailboxes) {
            SessionState s = m.session();
            if (s == null) {
                continue; // not a vehicle MailBox
            }
            String handle = m.address().substring(m.address().lastIndexOf('>') + 1);
            Vehicle had = byName.get(key(handle));
            String state = s.state().words();
            if (had != null && (had.fixTime() >= s.lastContact() || !s.hasPosition())) {
                byName.put(key(handle), new Vehicle(had.name(), m.address(), state, had.fixTime(), had.lat(), had.lon(),
                        had.source(), null, null));
            } else if (s.hasPosition()) {
                byName.put(key(handle), new Vehicle(had == null ? handle : had.name(), m.address(), state, s.lastContact(),
                        s.lat(), s.lon(), "console", null, null));
            } else {
                byName.put(key(handle), new Vehicle(handle, m.address(), state, 0, Double.NaN, Double.NaN, "", null, null));
            }
        }
        List<Vehicle> out = new ArrayList<>();
        for (Map.Entry<String, Vehicle> e : byName.entrySet()) {
            Vehicle v = e.getValue();
            double[][] t = track(tracks.getOrDefault(e.getKey(), List.of()));
            out.add(new Vehicle(v.name(), v.mailbox(), v.state(), v.fixTime(), v.lat(), v.lon(), v.source(), t[0], t[1]));
        }
        out.sort(Comparator.comparing(v -> v.name().toLowerCase(Locale.ROOT)));
        vehicles = List.copyOf(out);
    }

    /** Newest-first fixes to at most {@link #TRACK_POINTS}, oldest first, keeping the newest. */
    static double[][] track(List<double[]> newestFirst) {
        int n = newestFirst.size();
        int step = Math.max(1, (n + TRACK_POINTS - 1) / TRACK_POINTS);
        int size = (n + step - 1) / step;
        double[] lon = new double[size];
        double[] lat = new double[size];
        for (int i = 0; i < size; i++) {
            double[] p = newestFirst.get(i * step);
            lon[size - 1 - i] = p[0];
            lat[size - 1 - i] = p[1];
        }
        return new double[][] {lon, lat};
    }

    /** "just now", "12 min ago", "3 h 05 min ago", "2 days ago"; "no fix" for 0. */
    public static String age(long fixTime, long now) {
        if (fixTime <= 0) {
            return "no fix";
        }
        Duration d = Duration.ofMillis(Math.max(0, now - fixTime));
        if (d.toMinutes() < 1) {
            return "just now";
        }
        if (d.toHours() < 1) {
            return d.toMinutes() + " min ago";
        }
        if (d.toDays() < 2) {
            return String.format(Locale.ROOT, "%d h %02d min ago", d.toHours(), d.toMinutesPart());
        }
        return d.toDays() + " days ago";
    }

    /**
     * A database timestamp as epoch milliseconds UTC ({@code 2016-01-13 17:20:11.24094}, with
     * {@code T} or a trailing {@code Z} too), or 0 when it is not one.
     */
    static long time(String text) {
        if (text == null || text.isBlank()) {
            return 0;
        }
        String t = text.strip().replace(' ', 'T');
        if (t.endsWith("Z")) {
            t = t.substring(0, t.length() - 1);
        }
        try {
            return LocalDateTime.parse(t).toInstant(ZoneOffset.UTC).toEpochMilli();
        } catch (DateTimeParseException e) {
            return 0;
        }
    }

    private static String key(String name) {
        return name.toLowerCase(Locale.ROOT);
    }

    /** Columns found by name, in any case (Derby answers VEHICLE, PostgreSQL vehicle). */
    private static final class Columns {
        private final Map<String, Integer> index = new LinkedHashMap<>();

        Columns(TableResult t) {
            for (int i = 0; i < t.columns().size(); i++) {
                index.putIfAbsent(t.columns().get(i).toLowerCase(Locale.ROOT), i);
            }
        }

        String text(String[] row, String column) {
            Integer i = index.get(column);
            return i == null ? null : row[i];
        }

        double number(String[] row, String column) {
            String s = text(row, column);
            try {
                return s == null ? Double.NaN : Double.parseDouble(s.strip());
            } catch (NumberFormatException e) {
                return Double.NaN;
            }
        }
    }
}
