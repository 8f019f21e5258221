package org.ripv.plans;

import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;

/**
 * The behaviour names and b_arg units a Slocum's masterdata defines (the ones mission and
 * {@code .ma} files use), compared without regard to case as the glider does. A file naming
 * anything else would be refused by the glider when the mission loads, at sea, so it is refused here.
 */
final class SlocumVocabulary {
    static final Set<String> BEHAVIORS = Set.of("abend", "surface", "goto_list", "goto_wpt", "set_heading", "yo",
            "dive_to", "climb_to", "drift_at_depth", "prepare_to_dive", "sensors_in", "sample", "pinger_on_off",
            "nop_cmds", "die", "comatose");

    static final Set<String> UNITS = Set.of("nodim", "enum", "bool", "m", "cm", "km", "nm", "s", "sec", "secs", "min",
            "mins", "hours", "hrs", "days", "rad", "deg", "rad/s", "deg/s", "m/s", "cm/s", "m/s/s", "cc", "inhg", "volts",
            "amp", "amps", "amp-hrs", "%", "x", "byte", "bytes", "kbytes", "mbytes", "bar", "decibar", "dbar", "lat",
            "lon", "hz", "degc", "s/m", "ppt", "utc", "timestamp", "1/rad", "sec/m", "sec/rad", "counts", "uamp", "ma");

    private SlocumVocabulary() {
    }

    static boolean knownBehavior(String name) {
        return BEHAVIORS.contains(name.toLowerCase(Locale.ROOT));
    }

    static boolean knownUnit(String units) {
        return UNITS.contains(units.toLowerCase(Locale.ROOT));
    }

    static String behaviors() {
        return String.join(", ", new TreeSet<>(BEHAVIORS));
    }
}
