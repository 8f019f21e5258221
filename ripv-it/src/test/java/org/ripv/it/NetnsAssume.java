package org.ripv.it;

import org.junit.jupiter.api.Assumptions;

/** The multi-host tests' guard: skip (or under RIPV_REQUIRE_TOOLS fail) where network namespaces cannot be made. */
public final class NetnsAssume {
    private NetnsAssume() {}

    public static void usable() {
        check(Netns.unusable());
    }

    /** The same for a PostgreSQL cluster in a namespace ({@link Postgres}). */
    public static void postgres() {
        check(Postgres.unusable());
    }

    private static void check(String why) {
        if (why == null) {
            return;
        }
        if (System.getenv("RIPV_REQUIRE_TOOLS") != null) {
            throw new AssertionError("RIPV_REQUIRE_TOOLS is set but this test " + why);
        }
        Assumptions.abort(why);
    }
}
