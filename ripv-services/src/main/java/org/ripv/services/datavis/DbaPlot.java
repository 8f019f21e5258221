package org.ripv.services.datavis;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.ripv.messages.Attachment;
import org.ripv.services.ingest.DbaFormatException;
import org.ripv.services.ingest.DbaHeader;
import org.ripv.services.ingest.DbaReader;
import org.ripv.services.ingest.Sensor;

/**
 * {@code vis:file NAME x=SENSOR y=SENSOR[,SENSOR...] [out=NAME]}: columns of a Slocum DBA file from
 * the server's download directory as the data file of docs/datavis.md, read with the strict
 * {@link DbaReader} (positions in decimal degrees). An x that is a time ({@code timestamp} unit)
 * draws on a date axis; {@code m_depth} against time draws depth downwards; x a longitude and
 * y a latitude draws a track.
 *
 * @param file    the DBA file's name
 * @param x       the x sensor
 * @param ys      the y sensors
 * @param output  the picture's name (no extension)
 */
record DbaPlot(String file, String x, List<String> ys, String output) {
    /** The command word. */
    static final String PREFIX = "vis:file";

    static boolean matches(String line) {
        String l = line.strip().toLowerCase(Locale.ROOT);
        return l.equals(PREFIX) || l.startsWith(PREFIX + " ");
    }

    static DbaPlot parse(String line) {
        String[] words = line.strip().split("\\s+");
        String file = null;
        String x = null;
        List<String> ys = null;
        String out = null;
        for (int i = 1; i < words.length; i++) {
            String w = words[i];
            int eq = w.indexOf('=');
            if (eq < 0) {
                if (file != null) {
                    throw new IllegalArgumentException("vis:file plots one file; '" + w + "' is a second");
                }
                file = w;
                continue;
            }
            String v = w.substring(eq + 1);
            switch (w.substring(0, eq).toLowerCase(Locale.ROOT)) {
                case "x" -> x = v;
                case "y" -> ys = List.of(v.split(","));
                case "out" -> out = v.replaceFirst("(?i)\\.jpe?g$", "");
                default -> throw new IllegalArgumentException("unknown option '" + w.substring(0, eq) + "'; vis:file takes x=, y=, out=");
            }
        }
        if (file == null || x == null || ys == null || ys.isEmpty() || ys.contains("")) {
            throw new IllegalArgumentException("usage: vis:file NAME x=SENSOR y=SENSOR[,SENSOR...] [out=NAME], NAME a DBA"
                    + " file in the download directory (e.g. x=m_present_time y=m_depth)");
        }
        if (ys.size() > DataFile.MAX_COLUMNS - 1) {
            throw new IllegalArgumentException("at most " + (DataFile.MAX_COLUMNS - 1) + " y sensors");
        }
        String o = out != null ? out : VisCommand.defaultOutput(file) + "-" + ys.get(0);
        if (!Exchange.validOutputName(o)) {
            throw new IllegalArgumentException("out='" + o + "' is not a usable name: letters, digits, '_' and '-'");
        }
        return new DbaPlot(file, x, ys, o);
    }

    /** The data file for the plot. */
    byte[] data(Attachment dba) throws IOException, DataFormatException {
        try (DbaReader r = new DbaReader(new ByteArrayInputStream(dba.data()))) {
            DbaHeader h = r.header();
            int xc = column(h, x);
            int[] yc = new int[ys.size()];
            for (int i = 0; i < yc.length; i++) {
                yc[i] = column(h, ys.get(i));
            }
            Sensor xs = h.sensors().get(xc);
            boolean time = xs.unit().equals("timestamp");
            String style = time ? (ys.equals(List.of("m_depth")) ? "depth" : "time")
                    : xs.kind() == Sensor.Kind.LONGITUDE && h.sensors().get(yc[0]).kind() == Sensor.Kind.LATITUDE ? "track"
                    : ys.equals(List.of("m_depth")) ? "profile" : "xy";
            List<String> legend = new ArrayList<>();
            for (int c : yc) {
                legend.add(h.sensors().get(c).name() + " (" + h.sensors().get(c).unit() + ")");
            }
            StringBuilder b = new StringBuilder();
            b.append("% title: ").append(h.filename() != null ? h.filename() : file).append('\n');
            b.append("% xlabel: ").append(xs.name()).append(" (").append(xs.unit()).append(")\n");
            b.append("% legend: ").append(String.join(" | ", legend)).append('\n');
            b.append("% plot: ").append(style).append('\n');
            double[] row = new double[h.sensors().size()];
            long rows = 0;
            while (r.next(row)) {
                double xv = row[xc];
                boolean any = false;
                for (int c : yc) {
                    any |= !Double.isNaN(row[c]);
                }
                if (Double.isNaN(xv) || !any) {
                    continue; // a row without this plot's values is no gap: the sensors just did not report
                }
                b.append(xv);
                for (int c : yc) {
                    b.append(' ').append(Double.isNaN(row[c]) ? "NaN" : Double.toString(row[c]));
                }
                b.append('\n');
                rows++;
            }
            if (rows == 0) {
                throw new DataFormatException(0, file + " has no row with " + x + " and any of " + String.join(", ", ys));
            }
            return b.toString().getBytes(StandardCharsets.UTF_8);
        } catch (DbaFormatException e) {
            throw new DataFormatException(0, "not a usable DBA file: " + e.getMessage());
        }
    }

    private static int column(DbaHeader h, String name) throws DataFormatException {
        int c = h.column(name);
        if (c < 0) {
            throw new DataFormatException(0, "the file has no sensor '" + name + "'");
        }
        return c;
    }
}
