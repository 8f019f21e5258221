package org.ripv.services.ingest;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.ripv.services.bench.SyntheticDba;

/** The shared Slocum files (copied into test resources) and generated DBA files, with counts made without the reader. */
public final class DbaFiles {
    private DbaFiles() {}

    public static Path shared(String name) {
        try {
            return Path.of(DbaFiles.class.getResource("/slocum/" + name).toURI());
        } catch (Exception e) {
            throw new IllegalStateException("test resource /slocum/" + name + " is missing", e);
        }
    }

    /** An awk-like count of a DBA file: rows, sensors, non-NaN cells, and 69696969 cells in lat/lon columns. */
    public record Count(int rows, int sensors, long values, long noFix, long positionRows) {}

    public static Count count(byte[] file) {
        String[] lines = new String(file, StandardCharsets.ISO_8859_1).split("\r?\n");
        int tags = 0;
        for (String l : lines) {
            if (l.startsWith("num_ascii_tags:")) {
                tags = Integer.parseInt(l.substring(15).trim());
            }
        }
        String[] names = lines[tags].trim().split("\\s+");
        String[] units = lines[tags + 1].trim().split("\\s+");
        List<Integer> posCols = new ArrayList<>();
        int gpsLat = -1, gpsLon = -1, lat = -1, lon = -1;
        for (int i = 0; i < names.length; i++) {
            if (units[i].equals("lat") || units[i].equals("lon") || names[i].matches("m_gps_la[tn]|m_la[tn]|c_wpt_la[tn]")) {
                posCols.add(i);
            }
            switch (names[i]) {
                case "m_gps_lat" -> gpsLat = i;
                case "m_gps_lon" -> gpsLon = i;
                case "m_lat" -> lat = i;
                case "m_lon" -> lon = i;
                default -> { }
            }
        }
        int rows = 0;
        long values = 0, noFix = 0, positions = 0;
        for (int r = tags + 3; r < lines.length; r++) {
            if (lines[r].isBlank()) {
                continue;
            }
            String[] cells = lines[r].trim().split("\\s+");
            rows++;
            for (int i = 0; i < cells.length; i++) {
                if (cells[i].equals("NaN")) {
                    continue;
                }
                if (posCols.contains(i) && Double.parseDouble(cells[i]) == 69696969) {
                    noFix++;
                } else {
                    values++;
                }
            }
            positions += fix(cells, gpsLat, gpsLon) + fix(cells, lat, lon);
        }
        return new Count(rows, names.length, values, noFix, positions);
    }

    private static int fix(String[] cells, int a, int b) {
        if (a < 0 || b < 0 || cells[a].equals("NaN") || cells[b].equals("NaN")
                || Double.parseDouble(cells[a]) == 69696969 || Double.parseDouble(cells[b]) == 69696969) {
            return 0;
        }
        return 1;
    }

    public static byte[] read(Path p) {
        try {
            return Files.readAllBytes(p);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * A generated DBA file: {@code sensors} columns (m_present_time, m_gps_lat, m_gps_lon, m_depth,
     * then s_4...), {@code rows} rows, about half the cells NaN, a fix every tenth row.
     */
    public static byte[] generate(String glider, int sensors, int rows, long seed) {
        StringBuilder b = new StringBuilder(rows * sensors * 4 + 4096);
        b.append(header(glider, sensors));
        Random rnd = new Random(seed);
        double t = 1_700_000_000;
        for (int r = 0; r < rows; r++) {
            t += 4.25;
            b.append(t);
            b.append(' ').append(r % 10 == 0 ? "4130." + (1000 + r % 9000) : "NaN");
            b.append(' ').append(r % 10 == 0 ? "-7040." + (1000 + r % 9000) : "NaN");
            b.append(' ').append(Math.round(Math.abs(Math.sin(r / 50.0)) * 100000) / 100.0);
            for (int i = 4; i < sensors; i++) {
                b.append(' ');
                if (rnd.nextBoolean()) {
                    b.append("NaN");
                } else {
                    b.append(rnd.nextInt(100000) / 100.0);
                }
            }
            b.append(" \n");
        }
        return b.toString().getBytes(StandardCharsets.US_ASCII);
    }

    /** The header and label lines of {@link #generate}'s files: the bench's made-up sensors, mission TEST.MI. */
    public static String header(String glider, int sensors) {
        return SyntheticDba.header(glider, sensors, "TEST.MI");
    }
}
