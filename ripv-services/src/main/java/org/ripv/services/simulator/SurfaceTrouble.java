package org.ripv.services.simulator;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import java.util.Set;

/**
 * Trouble a simulated glider has on demand, for rehearsing alerts: an abort on the calls named
 * (it surfaces because of it, and its ABORT HISTORY shows it from then on), and a leak from a call
 * on (its aft leak detector reads 1.21 V; dry is about 2.5 V). Thread-safe.
 */
final class SurfaceTrouble {
    static final SurfaceTrouble NONE = new SurfaceTrouble(Set.of(), 0);
    static final String ABORT_CAUSE = "MS_ABORT_OVERDEPTH";
    static final String ABORT_DETAILS = "dive_to: depth 1012.3 > max depth 1000.0";
    private static final DateTimeFormatter ISO = DateTimeFormatter.ofPattern("yyyy-MM-dd'T'HH:mm:ss", Locale.ROOT)
            .withZone(ZoneOffset.UTC);

    private final Set<Integer> abortCalls;
    private final int leakFrom;
    private int aborts;
    private String lastTime;
    private String lastSegment;
    private String lastMission;

    /**
     * @param abortCalls the calls (1 for the first) that surface because of an abort
     * @param leakFrom   the first call with a leak, or 0 for none
     */
    SurfaceTrouble(Set<Integer> abortCalls, int leakFrom) {
        this.abortCalls = Set.copyOf(abortCalls);
        this.leakFrom = leakFrom;
    }

    /** Whether call {@code call} surfaces because of an abort; if so, the abort is counted now. */
    synchronized boolean aborted(int call, Instant now, String vehicle, String mission) {
        if (!abortCalls.contains(call)) {
            return false;
        }
        aborts++;
        lastTime = ISO.format(now.minusSeconds(1200));
        lastSegment = String.format(Locale.ROOT, "%s-%d (%04d.0000)", vehicle, call, call);
        lastMission = mission;
        return true;
    }

    boolean leaks(int call) {
        return leakFrom > 0 && call >= leakFrom;
    }

    /** The ABORT HISTORY block as a Slocum prints it. */
    synchronized String history() {
        StringBuilder b = new StringBuilder("ABORT HISTORY: total since reset: ").append(aborts).append("\r\n");
        if (aborts > 0) {
            b.append("ABORT HISTORY: last abort cause: ").append(ABORT_CAUSE).append("\r\n")
                    .append("ABORT HISTORY: last abort details: ").append(ABORT_DETAILS).append("\r\n")
                    .append("ABORT HISTORY: last abort time: ").append(lastTime).append("\r\n")
                    .append("ABORT HISTORY: last abort segment: ").append(lastSegment).append("\r\n")
                    .append("ABORT HISTORY: last abort mission: ").append(lastMission).append("\r\n");
        }
        return b.toString();
    }
}
