package org.ripv.services.ingest;

import java.io.IOException;

/**
 * A Slocum file's cycles as {@link DbaIngest} takes them, one at a time: DBA text through
 * {@link DbaReader}, binary through {@link BinaryCycles}. Either gives the same header (tags and
 * sensors) and rows of values — positions already in decimal degrees, NaN where a sensor had no
 * value — so a file is stored the same way whatever form it came in, with only one cycle in memory.
 */
public interface Cycles extends AutoCloseable {
    /** The header tags ({@code filename}, {@code mission_name}, …) and the columns. */
    DbaHeader header();

    /** Reads the next cycle into {@code values}, one per sensor; false at the end. */
    boolean next(double[] values) throws IOException, DbaFormatException, SlocumFormatException;

    /** The time of a cycle read by {@link #next}: m_present_time, else sci_m_present_time; NaN if neither. */
    double time(double[] values);

    /** Cycles read so far. */
    long rows();

    /** Position values that were {@value Degrees#NO_FIX} ("no fix"). */
    long noFix();

    /** Position values that are not DDMM.MMMM within range. */
    long impossible();

    /** What a file cut short left out once {@link #next} returned false ({@link SlocumBinaryReader#leftOut()}); empty if nothing. */
    default String leftOut() {
        return "";
    }

    @Override
    void close() throws IOException;
}
