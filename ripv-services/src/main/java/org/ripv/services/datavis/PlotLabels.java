package org.ripv.services.datavis;

import java.util.ArrayList;
import java.util.List;

/**
 * What a data file's {@code %} comment lines say about its plot: title, axis labels, legend and
 * picture size. A {@code null} field means "not given" (see {@link #or}).
 *
 * @param title  {@code % title: ...}
 * @param xLabel {@code % xlabel: ...}
 * @param yLabel {@code % ylabel: ...}
 * @param legend {@code % legend: a | b | c}, one name per series
 * @param width  {@code % size: WIDTHxHEIGHT}, pixels; 0 when not given
 * @param height as {@code width}
 * @param style  {@code % plot: xy|time|depth|track|profile}: how to draw (docs/datavis.md); null for xy
 * @param mark   {@code % mark: text}: a label for the last point (a track's newest fix), or null
 */
public record PlotLabels(String title, String xLabel, String yLabel, List<String> legend, int width, int height,
                         String style, String mark) {
    /** The drawing styles of {@code % plot:}. */
    public static final List<String> STYLES = List.of("xy", "time", "depth", "track", "profile");
    /** Default picture size, as MATLAB's default figure prints at 100 dpi. */
    public static final int DEFAULT_WIDTH = 800;
    public static final int DEFAULT_HEIGHT = 600;
    /** Limits on the picture size, so a typo cannot ask for a gigapixel JPEG. */
    public static final int MIN_SIZE = 100;
    public static final int MAX_SIZE = 4000;
    private static final int MAX_TEXT = 200;

    /** Nothing given. */
    public static final PlotLabels NONE = new PlotLabels(null, null, null, null, 0, 0);

    /** Labels of the default (xy) style without a mark. */
    public PlotLabels(String title, String xLabel, String yLabel, List<String> legend, int width, int height) {
        this(title, xLabel, yLabel, legend, width, height, null, null);
    }

    public PlotLabels {
        title = clean(title);
        xLabel = clean(xLabel);
        yLabel = clean(yLabel);
        style = clean(style);
        mark = clean(mark);
        if (style != null && !STYLES.contains(style)) {
            throw new IllegalArgumentException("'% plot: " + style + "' is not one of " + String.join(", ", STYLES));
        }
        if (legend != null) {
            List<String> names = new ArrayList<>();
            for (String n : legend) {
                names.add(clean(n).replace('|', '/'));
            }
            legend = List.copyOf(names);
        }
        if ((width != 0 || height != 0) && (width < MIN_SIZE || width > MAX_SIZE || height < MIN_SIZE || height > MAX_SIZE)) {
            throw new IllegalArgumentException("picture size " + width + "x" + height + " is outside "
                    + MIN_SIZE + ".." + MAX_SIZE + " pixels on a side");
        }
    }

    /** Each field of this one, or {@code other}'s where this one gives none. */
    public PlotLabels or(PlotLabels other) {
        return new PlotLabels(title != null ? title : other.title, xLabel != null ? xLabel : other.xLabel,
                yLabel != null ? yLabel : other.yLabel, legend != null ? legend : other.legend,
                width != 0 ? width : other.width, width != 0 ? height : other.height,
                style != null ? style : other.style, mark != null ? mark : other.mark);
    }

    /**
     * These labels with one more given by its name, as a data file's {@code % key: value} line and
     * a {@code vis:} command's {@code key=value} option name it: {@code title}, {@code xlabel},
     * {@code ylabel}, {@code legend} (split by {@link #splitLegend}), {@code mark} or {@code plot}.
     *
     * @throws IllegalArgumentException for any other key
     */
    public PlotLabels with(String key, String value) {
        return switch (key) {
            case "title" -> new PlotLabels(value, xLabel, yLabel, legend, width, height, style, mark);
            case "xlabel" -> new PlotLabels(title, value, yLabel, legend, width, height, style, mark);
            case "ylabel" -> new PlotLabels(title, xLabel, value, legend, width, height, style, mark);
            case "legend" -> new PlotLabels(title, xLabel, yLabel, splitLegend(value), width, height, style, mark);
            case "mark" -> new PlotLabels(title, xLabel, yLabel, legend, width, height, style, value);
            case "plot" -> new PlotLabels(title, xLabel, yLabel, legend, width, height, value, mark);
            default -> throw new IllegalArgumentException("'" + key + "' is not a plot label");
        };
    }

    /** These labels with the picture size (checked as the constructor checks it). */
    public PlotLabels withSize(int width, int height) {
        return new PlotLabels(title, xLabel, yLabel, legend, width, height, style, mark);
    }

    public int widthOrDefault() {
        return width == 0 ? DEFAULT_WIDTH : width;
    }

    public int heightOrDefault() {
        return height == 0 ? DEFAULT_HEIGHT : height;
    }

    /** Splits a legend line: entries separated by {@code |}, or by commas when there is no {@code |}. */
    public static List<String> splitLegend(String text) {
        String sep = text.indexOf('|') >= 0 ? "\\|" : ",";
        List<String> out = new ArrayList<>();
        for (String part : text.split(sep, -1)) {
            out.add(part.trim());
        }
        return out;
    }

    /** One line of plain text: control characters (a CR, a NUL) would break the file exchange. */
    private static String clean(String s) {
        if (s == null) {
            return null;
        }
        String t = s.replaceAll("\\p{Cntrl}", " ").trim();
        return t.length() > MAX_TEXT ? t.substring(0, MAX_TEXT) : t;
    }
}
