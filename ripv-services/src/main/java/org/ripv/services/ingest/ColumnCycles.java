package org.ripv.services.ingest;

/**
 * What {@link DbaReader} and {@link BinaryCycles} share once a header is read: the header, the
 * columns' rules ({@link CycleColumns}: time, positions to degrees) and the count of cycles read,
 * so that text and binary files answer {@link Cycles}' questions by the same code.
 */
abstract class ColumnCycles implements Cycles {
    private final DbaHeader header;
    final CycleColumns columns;
    private long rows;

    ColumnCycles(DbaHeader header) {
        this.header = header;
        this.columns = new CycleColumns(header);
    }

    /** A cycle was read whole. */
    final void counted() {
        rows++;
    }

    @Override
    public final DbaHeader header() {
        return header;
    }

    /** The time of a cycle read by {@link #next}: m_present_time, else sci_m_present_time; NaN if neither. */
    @Override
    public final double time(double[] values) {
        return columns.time(values);
    }

    /** Cycles read so far. */
    @Override
    public final long rows() {
        return rows;
    }

    /** Position values that were {@value Degrees#NO_FIX} ("no fix"). */
    @Override
    public final long noFix() {
        return columns.noFix();
    }

    /** Position values that are not DDMM.MMMM within range. */
    @Override
    public final long impossible() {
        return columns.impossible();
    }
}
