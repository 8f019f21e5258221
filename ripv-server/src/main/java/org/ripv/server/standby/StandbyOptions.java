package org.ripv.server.standby;

import java.time.Duration;
import java.util.function.Supplier;
import org.ripv.server.store.StoreLocation;
import picocli.CommandLine.Option;

/**
 * {@code ripv server}'s option for a hot standby (picocli mixin). With a PostgreSQL
 * {@code --state-db}, every server takes the lead before it serves; a second one started against
 * the same database stands by until the first is gone (docs/operations.md "A hot standby").
 */
public final class StandbyOptions {
    @Option(names = "--lead-check", defaultValue = "1000", paramLabel = "MS",
            description = "With a PostgreSQL --state-db: how often a standby asks for the lead and the active server checks"
                    + " that it still holds it (default ${DEFAULT-VALUE} ms).")
    long checkMillis = 1000;

    /** A new claim on the lead in the state database, for this server named {@code me} to the others. */
    public Supplier<Leadership> leads(StoreLocation db, String me) {
        if (checkMillis < 100 || checkMillis > 10_000) {
            throw new IllegalArgumentException("--lead-check takes 100 to 10000 ms, not " + checkMillis);
        }
        Duration check = Duration.ofMillis(checkMillis);
        // The holder notices within check + 3 s; the database drops a silent holder 3 s after that and more.
        Leadership.Timings t = new Leadership.Timings(check, Duration.ofSeconds(3), Duration.ofSeconds(4).plus(check),
                Duration.ofSeconds(1));
        return () -> new Leadership(db.jdbcUrl(), db.user(), db.password(), me, t);
    }
}
