package org.ripv.services.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import org.ripv.services.ingest.DbaText;
import org.ripv.services.ingest.SlocumSensor;

/**
 * Made-up Slocum DBA files of any width and length, for the benchmarks that ingest or plot them
 * (and the services' tests, which write theirs with the same header): the header is
 * {@link DbaText}'s, as {@code dbd2asc} prints it.
 */
public final class SyntheticDba {
    private SyntheticDba() {}

    /** m_present_time, m_gps_lat, m_gps_lon, m_depth, then s_4… ({@code nodim}, 4 bytes) up to {@code count} sensors. */
    public static List<SlocumSensor> sensors(int count) {
        List<SlocumSensor> s = new ArrayList<>(List.of(new SlocumSensor("m_present_time", "timestamp", 8),
                new SlocumSensor("m_gps_lat", "lat", 8), new SlocumSensor("m_gps_lon", "lon", 8), new SlocumSensor("m_depth", "m", 4)));
        for (int i = 4; i < count; i++) {
            s.add(new SlocumSensor("s_" + i, "nodim", 4));
        }
        return s;
    }

    /** The header and label lines of {@code glider}'s segment 2024-100-1-0 with {@link #sensors}{@code (sensors)}. */
    public static String header(String glider, int sensors, String mission) {
        StringBuilder b = new StringBuilder();
        try {
            DbaText.start(b, Map.of("filename", glider + "-2024-100-1-0", "the8x3_filename", "00010000", "filename_extension", "sbd",
                    "mission_name", mission, "fileopen_time", "Mon_Apr__8_12:00:00_2024"), sensors(sensors));
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a StringBuilder does not throw
        }
        return b.toString();
    }

    /**
     * A DBA file: {@link #sensors} columns; each cell after the first four present with probability
     * {@code fill}; a GPS fix on every row when {@code fixes}, else every 50th.
     */
    public static byte[] generate(String glider, int sensors, int rows, double fill, boolean fixes, long seed) {
        StringBuilder b = new StringBuilder(rows * sensors * 6 + 4096);
        b.append(header(glider, sensors, "BENCH.MI"));
        Random rnd = new Random(seed);
        double t = 1_712_577_600;
        for (int r = 0; r < rows; r++) {
            t += 2.5;
            b.append(String.format(Locale.ROOT, "%.5f", t));
            boolean fix = fixes || r % 50 == 0;
            b.append(' ').append(fix ? String.format(Locale.ROOT, "%.4f", 4130 + r * 0.0001 % 20) : "NaN");
            b.append(' ').append(fix ? String.format(Locale.ROOT, "%.4f", -7040 - r * 0.00013 % 15) : "NaN");
            b.append(' ').append(String.format(Locale.ROOT, "%.2f", Math.abs(Math.sin(r / 200.0)) * 900));
            for (int i = 4; i < sensors; i++) {
                b.append(' ');
                if (rnd.nextDouble() < fill) {
                    b.append(rnd.nextInt(1_000_000) / 1000.0);
                } else {
                    b.append("NaN");
                }
            }
            b.append(" \n");
        }
        return b.toString().getBytes(StandardCharsets.US_ASCII);
    }
}
