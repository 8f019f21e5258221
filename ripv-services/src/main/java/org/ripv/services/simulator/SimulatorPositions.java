package org.ripv.services.simulator;

/** The simulated glider's positions, for tests that check what it prints against what is parsed. */
public final class SimulatorPositions {
    private SimulatorPositions() {
    }

    /** Decimal degrees (north, east positive) on call {@code n}. */
    public static double[] position(int n) {
        return SurfaceDialog.position(n);
    }

    /** As the glider prints it: DDMM.MMM. */
    public static String format(double decimal) {
        return SurfaceDialog.degreesMinutes(decimal);
    }
}
