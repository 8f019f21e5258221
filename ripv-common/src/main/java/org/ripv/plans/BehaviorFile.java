package org.ripv.plans;

import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * A behaviour file that passed every check: its behaviour, its b_args in file order and, for a
 * goto file, its waypoints. {@code sha256} is of the bytes read, so a file is followed by content.
 */
public record BehaviorFile(String name, String behavior, List<BArg> bargs, List<Waypoint> waypoints, String sha256) {
    public BehaviorFile {
        bargs = List.copyOf(bargs);
        waypoints = List.copyOf(waypoints);
    }

    /** Whether this is a waypoint list ({@code goto_list}). */
    public boolean isGoto() {
        return behavior.toLowerCase(Locale.ROOT).equals("goto_list");
    }

    /** The b_arg of that name (the glider's names are case-insensitive), if the file sets it. */
    public Optional<BArg> barg(String argName) {
        return bargs.stream().filter(b -> b.name().equalsIgnoreCase(argName)).findFirst();
    }
}
