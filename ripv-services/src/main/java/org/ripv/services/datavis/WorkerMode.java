package org.ripv.services.datavis;

import java.util.Locale;

/** Which plot worker serves the DataVisServer's work directory. */
public enum WorkerMode {
    /** The built-in JFreeChart worker, a thread of the service (the default). */
    BUILTIN,
    /** {@code octave-cli} running {@code ripvOut.m}, started and restarted by the service. */
    OCTAVE,
    /** A worker started by hand in the work directory (the thesis's way: ripvOut.m in MATLAB). */
    NONE;

    /** Parses builtin|octave|none, any case. */
    public static WorkerMode parse(String s) {
        try {
            return valueOf(s.strip().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("worker '" + s + "' is not builtin, octave or none", e);
        }
    }

    @Override
    public String toString() {
        return name().toLowerCase(Locale.ROOT);
    }
}
