package org.ripv.services.slocum;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.ripv.services.ingest.DbaText;
import org.ripv.services.ingest.SensorListCache;
import org.ripv.services.ingest.SlocumBinaryReader;
import org.ripv.services.ingest.SlocumFormatException;
import org.ripv.services.ingest.SlocumSensor;

/**
 * Streams one decoded file, or a flight and science pair merged, to DBA text: the pair as
 * {@code dba_merge} makes it — the flight file's header, its sensors then the science file's,
 * every row of both in time order ({@code m_present_time}, {@code sci_m_present_time}), each
 * with NaN for the other file's sensors. Both files are read side by side, one row of each in memory.
 */
final class Merge {
    private final Appendable out;
    private final List<String> only;

    Merge(Appendable out, List<String> only) {
        this.out = out;
        this.only = only;
    }

    /** Prints one file; returns what a file cut short of its end left out, or empty. */
    String one(InputStream in, String name, SensorListCache cache) throws IOException, SlocumFormatException {
        try (SlocumBinaryReader r = SlocumBinaryReader.open(in, name, cache)) {
            int[] pick = pick(r.sensors());
            DbaText text = DbaText.start(out, r.tags(), select(r.sensors(), pick));
            double[] row = new double[r.sensors().size()];
            double[] shown = new double[pick.length];
            while (r.next(row)) {
                for (int i = 0; i < pick.length; i++) {
                    shown[i] = row[pick[i]];
                }
                text.row(shown);
            }
            return r.leftOut();
        }
    }

    void run(InputStream a, String nameA, InputStream b, String nameB, SensorListCache cache) throws IOException, SlocumFormatException {
        try (SlocumBinaryReader ra = SlocumBinaryReader.open(a, nameA, cache);
             SlocumBinaryReader rb = SlocumBinaryReader.open(b, nameB, cache)) {
            int ta = time(ra, nameA);
            int tb = time(rb, nameB);
            List<SlocumSensor> all = new ArrayList<>(ra.sensors());
            all.addAll(rb.sensors());
            int[] pick = pick(all);
            Map<String, String> tags = new LinkedHashMap<>(ra.tags());
            DbaText text = DbaText.start(out, tags, select(all, pick));
            int na = ra.sensors().size();
            double[] rowA = new double[na];
            double[] rowB = new double[rb.sensors().size()];
            double[] merged = new double[all.size()];
            double[] shown = new double[pick.length];
            boolean hasA = ra.next(rowA);
            boolean hasB = rb.next(rowB);
            while (hasA || hasB) {
                boolean takeA = hasA && (!hasB || !(rowB[tb] < rowA[ta]));
                Arrays.fill(merged, Double.NaN);
                if (takeA) {
                    System.arraycopy(rowA, 0, merged, 0, na);
                    hasA = ra.next(rowA);
                } else {
                    System.arraycopy(rowB, 0, merged, na, rowB.length);
                    hasB = rb.next(rowB);
                }
                for (int i = 0; i < pick.length; i++) {
                    shown[i] = merged[pick[i]];
                }
                text.row(shown);
            }
        }
    }

    private static int time(SlocumBinaryReader r, String name) {
        for (String t : List.of("m_present_time", "sci_m_present_time")) {
            for (int i = 0; i < r.sensors().size(); i++) {
                if (r.sensors().get(i).name().equals(t)) {
                    return i;
                }
            }
        }
        throw new IllegalArgumentException(name + " has no m_present_time or sci_m_present_time sensor to merge by");
    }

    private int[] pick(List<SlocumSensor> sensors) {
        if (only == null || only.isEmpty()) {
            int[] all = new int[sensors.size()];
            for (int i = 0; i < all.length; i++) {
                all[i] = i;
            }
            return all;
        }
        List<Integer> found = new ArrayList<>();
        for (String want : only) {
            boolean seen = false;
            for (int i = 0; i < sensors.size(); i++) {
                if (sensors.get(i).name().equalsIgnoreCase(want.trim())) {
                    seen = true;
                    if (!found.contains(i)) {
                        found.add(i);
                    }
                }
            }
            if (!seen) {
                throw new IllegalArgumentException("--sensors: '" + want + "' is not a sensor of the file (it has "
                        + sensors.size() + " in its cycle; decode without --sensors to see them)");
            }
        }
        return found.stream().sorted().mapToInt(Integer::intValue).toArray();
    }

    private static List<SlocumSensor> select(List<SlocumSensor> sensors, int[] pick) {
        List<SlocumSensor> s = new ArrayList<>(pick.length);
        for (int i : pick) {
            s.add(sensors.get(i));
        }
        return s;
    }
}
