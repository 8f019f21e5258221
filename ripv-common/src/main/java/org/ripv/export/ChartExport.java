package org.ripv.export;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.ripv.json.Json;
import org.ripv.messages.ChartData;

/**
 * A plot's data ({@link ChartData}) as CSV — one line per point: {@code series,unit,x,y}, and for
 * a time axis also {@code time_utc} in ISO-8601, a gap as an empty y — or as JSON:
 * {@code {"title", "kind", "xLabel", "yLabel", "rows", "reduced", "series": [{"name", "unit",
 * "x": [...], "y": [...]}], "newest": {"x", "y", "label"}}} with numbers as numbers and a gap as null.
 */
public final class ChartExport {
    private ChartExport() {}

    public static String csv(ChartData c) {
        boolean time = c.kind().timeAxis();
        StringBuilder b = new StringBuilder(64 + (int) Math.min(Integer.MAX_VALUE / 2, c.points() * 32));
        TableExport.line(b, time ? List.of("series", "unit", "x", "time_utc", "y") : List.of("series", "unit", "x", "y"));
        List<String> f = new ArrayList<>(5);
        for (ChartData.Series s : c.series()) {
            for (int i = 0; i < s.size(); i++) {
                f.clear();
                f.add(s.name());
                f.add(s.unit());
                double x = s.x()[i];
                f.add(number(x));
                if (time) {
                    f.add(Double.isFinite(x) ? Instant.ofEpochMilli((long) x).toString() : null);
                }
                f.add(number(s.y()[i]));
                TableExport.line(b, f);
            }
        }
        return b.toString();
    }

    public static String json(ChartData c) {
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("title", c.title());
        doc.put("kind", c.kind().name().toLowerCase(Locale.ROOT));
        doc.put("xLabel", c.xLabel());
        doc.put("yLabel", c.yLabel());
        doc.put("xIsEpochMillis", c.kind().timeAxis());
        doc.put("yInverted", c.kind().yInverted());
        doc.put("rows", c.rows());
        doc.put("reduced", c.reduced());
        List<Object> series = new ArrayList<>();
        for (ChartData.Series s : c.series()) {
            Map<String, Object> o = new LinkedHashMap<>();
            o.put("name", s.name());
            o.put("unit", s.unit());
            o.put("x", boxed(s.x()));
            o.put("y", boxed(s.y()));
            series.add(o);
        }
        doc.put("series", series);
        if (c.newest() != null) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("x", c.newest().x());
            m.put("y", c.newest().y());
            m.put("label", c.newest().label());
            doc.put("newest", m);
        }
        return Json.write(doc) + "\n";
    }

    /** A number as written in CSV: integral values without ".0", a gap empty. */
    static String number(double v) {
        if (!Double.isFinite(v)) {
            return null;
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return Double.toString(v);
    }

    private static List<Object> boxed(double[] a) {
        List<Object> out = new ArrayList<>(a.length);
        for (double d : a) {
            out.add(Double.isFinite(d) && d == Math.rint(d) && Math.abs(d) < 1e15 ? (Object) (long) d : (Object) d);
        }
        return out;
    }
}
