package org.ripv.messages;

import java.io.Serializable;
import java.util.List;
import java.util.Objects;

/**
 * The numbers a DataVisServer plot was drawn from, so a client can redraw it interactively
 * (zoom, pan, the value under the cursor, export) instead of showing only the JPEG. It travels
 * inside an {@link ImageResult}; a worker that draws on its own (Octave, MATLAB) sends none.
 *
 * <p>Bounded, whoever built it: at most {@link #MAX_SERIES} series, {@link #MAX_POINTS_PER_SERIES}
 * points a series and {@link #MAX_POINTS} in all (about 3 MB of numbers); texts are cut at
 * {@link #MAX_TEXT} characters. The checks run in the canonical constructor, which Java also runs
 * when it deserializes a record, so an oversized or inconsistent chart from the wire is refused.
 *
 * @param kind    how to draw it
 * @param title   the chart's title ("" for none)
 * @param xLabel  the x axis' label, unit included ("time (UTC)", "longitude (degrees east)")
 * @param yLabel  the y axis' label
 * @param series  the series, in legend order
 * @param newest  the newest fix of a track (marked and labelled), or null
 * @param rows    rows of the data the plot was made from (before any reduction)
 * @param reduced true when the series hold fewer points than {@code rows} (reduced for the wire)
 */
public record ChartData(Kind kind, String title, String xLabel, String yLabel, List<Series> series, Mark newest,
                        long rows, boolean reduced) implements Serializable {
    /** At most this many series (a data file's 64 columns less x). */
    public static final int MAX_SERIES = 63;
    /** At most this many points in one series. */
    public static final int MAX_POINTS_PER_SERIES = 20_000;
    /** At most this many points in all series together. */
    public static final int MAX_POINTS = 200_000;
    /** Texts longer than this are cut. */
    public static final int MAX_TEXT = 200;

    /**
     * How a chart is drawn. {@link #TIME} and {@link #DEPTH} have x in epoch milliseconds (UTC);
     * {@link #DEPTH} and {@link #PROFILE} draw y (depth) growing downwards; {@link #TRACK} has x
     * longitude and y latitude in decimal degrees, drawn at the aspect right for the latitude.
     */
    public enum Kind {
        XY, TIME, DEPTH, PROFILE, TRACK;

        /** Whether x is a time (epoch milliseconds, UTC). */
        public boolean timeAxis() {
            return this == TIME || this == DEPTH;
        }

        /** Whether y grows downwards (depth). */
        public boolean yInverted() {
            return this == DEPTH || this == PROFILE;
        }
    }

    /**
     * One series: its name, unit and points. A NaN y is a gap (the line breaks there).
     *
     * @param name the legend's name
     * @param unit the unit of y ("" when unknown)
     * @param x    x values, as many as {@code y}
     * @param y    y values
     */
    public record Series(String name, String unit, double[] x, double[] y) implements Serializable {
        public Series {
            name = cut(name);
            unit = cut(unit);
            Objects.requireNonNull(x, "x");
            Objects.requireNonNull(y, "y");
            if (x.length != y.length) {
                throw new IllegalArgumentException("series '" + name + "' has " + x.length + " x but " + y.length + " y values");
            }
            if (x.length > MAX_POINTS_PER_SERIES) {
                throw new IllegalArgumentException("series '" + name + "' has " + x.length + " points; at most "
                        + MAX_POINTS_PER_SERIES);
            }
        }

        /** Points in this series. */
        public int size() {
            return x.length;
        }

        @Override
        public String toString() {
            return "Series[" + name + (unit.isEmpty() ? "" : " (" + unit + ")") + ", " + x.length + " points]";
        }
    }

    /**
     * A marked point: a track's newest fix.
     *
     * @param x     its x (longitude)
     * @param y     its y (latitude)
     * @param label what it says ("newest fix 2013-09-05 13:45:50 UTC (gps)")
     */
    public record Mark(double x, double y, String label) implements Serializable {
        public Mark {
            label = cut(label);
        }
    }

    public ChartData {
        Objects.requireNonNull(kind, "kind");
        title = cut(title);
        xLabel = cut(xLabel);
        yLabel = cut(yLabel);
        series = List.copyOf(series);
        if (series.size() > MAX_SERIES) {
            throw new IllegalArgumentException(series.size() + " series; at most " + MAX_SERIES);
        }
        long points = 0;
        for (Series s : series) {
            points += Objects.requireNonNull(s, "series").size();
        }
        if (points > MAX_POINTS) {
            throw new IllegalArgumentException(points + " points; at most " + MAX_POINTS + " in one chart");
        }
        if (rows < 0) {
            throw new IllegalArgumentException("rows " + rows);
        }
    }

    /** Points in all series. */
    public long points() {
        long n = 0;
        for (Series s : series) {
            n += s.size();
        }
        return n;
    }

    private static String cut(String s) {
        if (s == null) {
            return "";
        }
        return s.length() > MAX_TEXT ? s.substring(0, MAX_TEXT) : s;
    }

    @Override
    public String toString() {
        return "ChartData[" + kind + " '" + title + "', " + series.size() + " series, " + points() + " points of " + rows
                + " rows" + (reduced ? ", reduced" : "") + "]";
    }
}
