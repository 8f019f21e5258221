package org.ripv.services.ingest;

/**
 * What every {@link Cycles} reader does with a cycle's columns, text or binary alike: its time
 * (m_present_time, else sci_m_present_time) and its positions (DDMM.MMMM to decimal degrees, "no
 * fix" and impossible values to NaN, counted).
 */
final class CycleColumns {
    private final int timeColumn;
    private final int sciTimeColumn;
    private final Sensor.Kind[] kinds;
    private long noFix;
    private long impossible;

    CycleColumns(DbaHeader header) {
        this.timeColumn = header.column("m_present_time");
        this.sciTimeColumn = header.column("sci_m_present_time");
        this.kinds = new Sensor.Kind[header.sensors().size()];
        for (Sensor s : header.sensors()) {
            kinds[s.index()] = s.kind();
        }
    }

    /** False when the cycles have no time sensor at all. */
    boolean timed() {
        return timeColumn >= 0 || sciTimeColumn >= 0;
    }

    double time(double[] values) {
        double t = timeColumn >= 0 ? values[timeColumn] : Double.NaN;
        if (Double.isNaN(t) && sciTimeColumn >= 0) {
            t = values[sciTimeColumn];
        }
        return t;
    }

    /** True for a latitude or longitude column. */
    boolean isPosition(int column) {
        return kinds[column] != Sensor.Kind.PLAIN;
    }

    /** A position column's value in decimal degrees, or NaN (counted) for "no fix" and impossible ones. */
    double degrees(int column, double ddmm) {
        if (ddmm == Degrees.NO_FIX) {
            noFix++;
            return Double.NaN;
        }
        double d = Degrees.fromDdmm(ddmm, kinds[column] == Sensor.Kind.LATITUDE ? 90 : 180);
        if (Double.isNaN(d)) {
            impossible++;
        }
        return d;
    }

    long noFix() {
        return noFix;
    }

    long impossible() {
        return impossible;
    }
}
