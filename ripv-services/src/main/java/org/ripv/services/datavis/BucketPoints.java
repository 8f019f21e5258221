package org.ripv.services.datavis;

/**
 * The few points an M4 bucket keeps (first, lowest, highest, last, a gap), in row order: shared
 * by the worker's drawing ({@link PlotRenderer}) and the client's chart data ({@link ChartDataBuilder}),
 * which must reduce a file to the same points.
 */
final class BucketPoints {
    private BucketPoints() {}

    /**
     * Adds a point unless its row is there already, keeping the first {@code k} points in row
     * order; returns how many there are now.
     */
    static int insert(long[] rows, double[] px, double[] py, int k, long row, double x, double y) {
        int j = 0;
        while (j < k && rows[j] < row) {
            j++;
        }
        if (j < k && rows[j] == row) {
            return k;
        }
        System.arraycopy(rows, j, rows, j + 1, k - j);
        System.arraycopy(px, j, px, j + 1, k - j);
        System.arraycopy(py, j, py, j + 1, k - j);
        rows[j] = row;
        px[j] = x;
        py[j] = y;
        return k + 1;
    }
}
