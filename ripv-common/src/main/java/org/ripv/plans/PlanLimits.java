package org.ripv.plans;

/**
 * What a behaviour file may cost. {@code maxWaypoints} is what the firmware takes: masterdata's
 * {@code goto_list} says "maximum of 8 (this can be increased at compile-time)", so 8 unless a
 * site's firmware was built with more. The rest bound hostile files: real {@code .ma} files are a
 * few KiB with lines under 200 characters.
 */
public record PlanLimits(int maxWaypoints, int maxBytes, int maxLineChars, int maxProblems) {
    /** The firmware's stock limit on a goto list. */
    public static final int FIRMWARE_WAYPOINTS = 8;
    public static final PlanLimits DEFAULT = new PlanLimits(FIRMWARE_WAYPOINTS, 256 * 1024, 1024, 50);

    public PlanLimits {
        if (maxWaypoints < 1 || maxWaypoints > 10_000) {
            throw new IllegalArgumentException("the waypoint limit is 1 to 10000, not " + maxWaypoints);
        }
        if (maxBytes < 1 || maxLineChars < 16 || maxProblems < 1) {
            throw new IllegalArgumentException("limits must be positive");
        }
    }

    /** These limits with another firmware waypoint limit. */
    public PlanLimits withMaxWaypoints(int n) {
        return new PlanLimits(n, maxBytes, maxLineChars, maxProblems);
    }
}
