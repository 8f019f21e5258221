package org.ripv.dac;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.ripv.services.ingest.Degrees;
import org.ripv.services.ingest.SensorListCache;
import org.ripv.services.ingest.SlocumBinaryReader;
import org.ripv.services.ingest.SlocumFormatException;
import org.ripv.services.ingest.SlocumSensor;

/**
 * Decodes a glider's files — flight ({@code .sbd .dbd}, compressed {@code .scd .dcd}) and science
 * ({@code .tbd .ebd}, {@code .tcd .ecd}), in any order — into one {@link Segment} per segment
 * (the header's {@code full_filename}), with the project's Slocum decoder. A file is read as a
 * stream and only the columns profiles use are kept; a file that decompresses past
 * {@value #MAX_BYTES} bytes is refused (an LZ4 bomb is stopped there, not read to its end).
 */
public final class SegmentReader {
    /** The most decompressed bytes one file may have: a month-long .ebd is a few hundred MB less than this. */
    public static final long MAX_BYTES = 512L << 20;

    private final SensorListCache cache;
    private final long maxBytes;

    public SegmentReader(SensorListCache cache) {
        this(cache, MAX_BYTES);
    }

    SegmentReader(SensorListCache cache, long maxBytes) {
        this.cache = cache;
        this.maxBytes = maxBytes;
    }

    /** Decoded columns of one file. */
    private record Columns(String file, String segment, boolean science, boolean delayed, Map<String, double[]> values) {
    }

    /** The segments of these files, in name order; every science file needs its flight file. */
    public List<Segment> read(List<Path> files) throws DacException, IOException {
        Map<String, Columns> flight = new TreeMap<>();
        Map<String, Columns> science = new TreeMap<>();
        for (Path f : files) {
            Columns c = decode(f);
            Map<String, Columns> side = c.science() ? science : flight;
            String key = c.segment() + (c.delayed() ? "/delayed" : "/rt");
            if (side.containsKey(key)) {
                throw new DacException(f.getFileName() + ": the segment " + c.segment() + " is given twice ("
                        + side.get(key).file() + " and " + c.file() + ")");
            }
            side.put(key, c);
        }
        if (science.isEmpty()) {
            throw new DacException("no science file among " + names(files) + ": profiles need a .tbd/.ebd (or .tcd/.ecd)"
                    + " with sci_water_pressure, sci_water_temp and sci_water_cond");
        }
        // Fixes from every flight file given: the fix after a dive is often in the next segment's file.
        List<Columns> allFlight = new ArrayList<>(flight.values());
        Segment.Track gps = track(allFlight, "m_gps_lat", "m_gps_lon");
        List<Segment> out = new ArrayList<>();
        for (Map.Entry<String, Columns> e : science.entrySet()) {
            Columns sci = e.getValue();
            Columns fl = flight.get(e.getKey());
            if (fl == null) {
                throw new DacException(sci.file() + ": its flight file (" + (sci.delayed() ? ".dbd/.dcd" : ".sbd/.scd")
                        + " of " + sci.segment() + ") is not among the files given: the profiles' positions come from it");
            }
            out.add(segment(sci, fl, gps));
        }
        return out;
    }

    private static String names(List<Path> files) {
        return files.stream().map(p -> p.getFileName().toString()).toList().toString();
    }

    private Segment segment(Columns sci, Columns fl, Segment.Track gps) throws DacException {
        double[] t = sci.values().get("sci_m_present_time");
        double[] p = sci.values().get("sci_water_pressure");
        double[] temp = sci.values().get("sci_water_temp");
        double[] cond = sci.values().get("sci_water_cond");
        if (t == null || p == null || temp == null || cond == null) {
            throw new DacException(sci.file() + ": no science to profile: it lacks "
                    + missing(sci, "sci_m_present_time", "sci_water_pressure", "sci_water_temp", "sci_water_cond"));
        }
        int n = 0;
        double lastTime = Double.NEGATIVE_INFINITY;
        int rows = t.length;
        double[] ot = new double[rows], op = new double[rows], otemp = new double[rows], ocond = new double[rows];
        for (int i = 0; i < rows; i++) {
            if (!Double.isFinite(p[i]) || !Double.isFinite(t[i])) {
                continue;
            }
            if (t[i] <= lastTime) {
                throw new DacException(sci.file() + ": the clock steps back at row " + (i + 1) + ": sci_m_present_time "
                        + t[i] + " after " + lastTime + "; profile files need time strictly increasing, so none is written for "
                        + sci.segment());
            }
            lastTime = t[i];
            ot[n] = t[i];
            op[n] = p[i];
            otemp[n] = temp[i];
            ocond[n] = cond[i];
            n++;
        }
        if (n == 0) {
            throw new DacException(sci.file() + ": no science to profile: no row has sci_water_pressure");
        }
        boolean anyCtd = false;
        for (int i = 0; i < n && !anyCtd; i++) {
            anyCtd = Double.isFinite(otemp[i]) || Double.isFinite(ocond[i]);
        }
        if (!anyCtd) {
            throw new DacException(sci.file() + ": the CTD gave no temperature or conductivity (all " + n + " are NaN): no profile to deliver");
        }
        Segment.Track dr = track(List.of(fl), "m_lat", "m_lon");
        double[] ft = fl.values().get("m_present_time");
        double[] vx = fl.values().get("m_water_vx");
        double[] vy = fl.values().get("m_water_vy");
        double uvTime = Double.NaN, u = Double.NaN, v = Double.NaN;
        if (ft != null && vx != null && vy != null) {
            for (int i = ft.length - 1; i >= 0; i--) {
                if (Double.isFinite(vx[i]) && Double.isFinite(vy[i]) && Double.isFinite(ft[i]) && Math.abs(vx[i]) < 10 && Math.abs(vy[i]) < 10) {
                    uvTime = ft[i];
                    u = vx[i];
                    v = vy[i];
                    break;
                }
            }
        }
        String vehicle = sci.segment().contains("-") ? sci.segment().substring(0, sci.segment().indexOf('-')) : sci.segment();
        return new Segment(sci.segment(), vehicle, sci.delayed(), sci.file(),
                Arrays.copyOf(ot, n), Arrays.copyOf(op, n), Arrays.copyOf(otemp, n),
                Arrays.copyOf(ocond, n), gps, dr, uvTime, u, v);
    }

    private static String missing(Columns c, String... names) {
        List<String> m = new ArrayList<>();
        for (String n : names) {
            if (!c.values().containsKey(n)) {
                m.add(n);
            }
        }
        return String.join(", ", m);
    }

    /** Valid positions (DDMM converted, the glider's 69696969 "no fix" and impossible values left out) in time order. */
    private static Segment.Track track(List<Columns> files, String latName, String lonName) {
        TreeMap<Double, double[]> byTime = new TreeMap<>();
        for (Columns c : files) {
            double[] t = c.values().get("m_present_time");
            double[] la = c.values().get(latName);
            double[] lo = c.values().get(lonName);
            if (t == null || la == null || lo == null) {
                continue;
            }
            for (int i = 0; i < t.length; i++) {
                double lat = Degrees.fromDdmm(la[i], 90);
                double lon = Degrees.fromDdmm(lo[i], 180);
                if (Double.isFinite(t[i]) && Double.isFinite(lat) && Double.isFinite(lon) && la[i] != Degrees.NO_FIX) {
                    byTime.put(t[i], new double[] {lat, lon});
                }
            }
        }
        double[] t = new double[byTime.size()], lat = new double[byTime.size()], lon = new double[byTime.size()];
        int i = 0;
        for (Map.Entry<Double, double[]> e : byTime.entrySet()) {
            t[i] = e.getKey();
            lat[i] = e.getValue()[0];
            lon[i] = e.getValue()[1];
            i++;
        }
        return new Segment.Track(t, lat, lon);
    }

    private static final List<String> FLIGHT = List.of("m_present_time", "m_gps_lat", "m_gps_lon", "m_lat", "m_lon", "m_water_vx", "m_water_vy");
    private static final List<String> SCIENCE = List.of("sci_m_present_time", "sci_water_pressure", "sci_water_temp", "sci_water_cond");

    private Columns decode(Path f) throws DacException, IOException {
        String name = f.getFileName().toString();
        String ext = name.contains(".") ? name.substring(name.lastIndexOf('.') + 1).toLowerCase(Locale.ROOT) : "";
        if (!SlocumBinaryReader.isBinaryName(name)) {
            throw new DacException(name + ": not a Slocum data file name (.sbd .tbd .dbd .ebd, or compressed .scd .tcd .dcd .ecd)");
        }
        char kind = ext.charAt(0);
        boolean science = kind == 't' || kind == 'e';
        boolean delayed = kind == 'd' || kind == 'e';
        if (!science && kind != 's' && kind != 'd') {
            throw new DacException(name + ": ." + ext + " files are not a flight or science file of a segment (.sbd .tbd .dbd .ebd)");
        }
        try (InputStream in = Files.newInputStream(f); SlocumBinaryReader r = SlocumBinaryReader.open(in, name, cache)) {
            String segment = r.tags().getOrDefault("full_filename", name.substring(0, name.lastIndexOf('.')));
            List<String> wanted = science ? SCIENCE : FLIGHT;
            Map<String, Integer> index = new HashMap<>();
            List<SlocumSensor> sensors = r.sensors();
            for (int i = 0; i < sensors.size(); i++) {
                if (wanted.contains(sensors.get(i).name())) {
                    index.put(sensors.get(i).name(), i);
                }
            }
            Map<String, DoubleList> cols = new LinkedHashMap<>();
            for (String w : wanted) {
                if (index.containsKey(w)) {
                    cols.put(w, new DoubleList());
                }
            }
            double[] row = new double[sensors.size()];
            while (r.next(row)) {
                if (r.offset() > maxBytes) {
                    throw new DacException(name + ": more than " + maxBytes + " bytes decompressed and no end in sight:"
                            + " not a glider's segment file (a decompression bomb?); refused");
                }
                for (Map.Entry<String, DoubleList> e : cols.entrySet()) {
                    e.getValue().add(row[index.get(e.getKey())]);
                }
            }
            Map<String, double[]> values = new HashMap<>();
            cols.forEach((k, v) -> values.put(k, v.toArray()));
            return new Columns(name, segment, science, delayed, values);
        } catch (NoSuchFileException e) {
            throw new DacException(name + ": no such file (" + f + ")");
        } catch (SlocumFormatException e) {
            throw new DacException(e.getMessage(), e);
        }
    }

    /** A growable array of doubles: a segment's column without boxing. */
    static final class DoubleList {
        private double[] a = new double[1024];
        private int n;

        void add(double d) {
            if (n == a.length) {
                a = Arrays.copyOf(a, n * 2);
            }
            a[n++] = d;
        }

        double[] toArray() {
            return Arrays.copyOf(a, n);
        }
    }
}
