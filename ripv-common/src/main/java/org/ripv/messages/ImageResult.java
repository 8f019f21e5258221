package org.ripv.messages;

import java.util.Objects;

/**
 * A picture (a DataVisServer plot): its file name, the JPEG bytes and, when the worker that drew
 * it can say (the built-in one), the numbers it was drawn from, for an interactive chart in the
 * client. The JPEG is always there: it is what the server stores in its download directory, what
 * the CLI saves, and all an Octave or MATLAB worker gives.
 *
 * @param name  the picture's file name ({@code track-cp_388.jpg})
 * @param jpeg  the JPEG
 * @param chart the chart's data, or null
 */
public record ImageResult(String name, byte[] jpeg, ChartData chart) implements Result {
    public ImageResult {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(jpeg, "jpeg");
    }

    /** A picture without chart data. */
    public ImageResult(String name, byte[] jpeg) {
        this(name, jpeg, null);
    }

    @Override
    public String toString() {
        return "ImageResult[" + name + ", " + jpeg.length + " bytes" + (chart == null ? "" : ", " + chart) + "]";
    }
}
