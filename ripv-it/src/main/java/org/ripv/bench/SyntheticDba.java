package org.ripv.bench;

import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Random;

/** Made-up Slocum DBA files of any width and length, for the benchmarks that ingest or plot them. */
final class SyntheticDba {
    private SyntheticDba() {}

    /**
     * A DBA file: m_present_time, m_gps_lat, m_gps_lon, m_depth, then s_4...; each other cell
     * present with probability {@code fill}; a GPS fix on every row when {@code fixes}, else every 50th.
     */
    static byte[] generate(String glider, int sensors, int rows, double fill, boolean fixes, long seed) {
        StringBuilder b = new StringBuilder(rows * sensors * 6 + 4096);
        b.append("dbd_label: DBD_ASC(dinkum_binary_data_ascii)file\nencoding_ver: 2\nnum_ascii_tags: 14\nall_sensors: 0\n");
        b.append("filename: ").append(glider).append("-2024-100-1-0\nthe8x3_filename: 00010000\nfilename_extension: sbd\n");
        b.append("filename_label: ").append(glider).append("-2024-100-1-0-sbd(00010000)\nmission_name: BENCH.MI\n");
        b.append("fileopen_time: Mon_Apr__8_12:00:00_2024\nsensors_per_cycle: ").append(sensors).append('\n');
        b.append("num_label_lines: 3\nnum_segments: 1\nsegment_filename_0: ").append(glider).append("-2024-100-1-0\n");
        StringBuilder names = new StringBuilder("m_present_time m_gps_lat m_gps_lon m_depth");
        StringBuilder units = new StringBuilder("timestamp lat lon m");
        StringBuilder bytes = new StringBuilder("8 8 8 4");
        for (int i = 4; i < sensors; i++) {
            names.append(" s_").append(i);
            units.append(" nodim");
            bytes.append(" 4");
        }
        b.append(names).append(" \n").append(units).append(" \n").append(bytes).append(" \n");
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
