package org.ripv.server.standby;

import java.nio.file.Path;
import java.time.Duration;
import picocli.CommandLine.Option;

/**
 * {@code ripv server}'s options for a hot standby (picocli mixin). With a PostgreSQL
 * {@code --state-db}, every server takes the lead before it serves; a second one started against
 * the same database stands by until the first is gone.
 */
public final class StandbyOptions {
    /** Where the state database's password may come from instead of a file. */
    public static final String PASSWORD_ENV = "RIPV_STATE_DB_PASSWORD";

    @Option(names = "--state-db", paramLabel = "JDBC_URL",
            description = "The PostgreSQL state database (jdbc:postgresql://HOST[:PORT]/DB). Servers sharing it take turns:"
                    + " one serves, the others stand by and take over when it dies (docs/operations.md).")
    String url;

    @Option(names = "--state-db-user", paramLabel = "USER", description = "The state database's user.")
    String user;

    @Option(names = "--state-db-password-file", paramLabel = "FILE",
            description = "File whose first line is the state database's password (else $" + PASSWORD_ENV + ").")
    Path passwordFile;

    @Option(names = "--lead-check", defaultValue = "1000", paramLabel = "MS",
            description = "How often a standby asks for the lead and the active server checks it holds it (default ${DEFAULT-VALUE} ms).")
    long checkMillis;

    /** True when servers take turns (a PostgreSQL state database was given). */
    public boolean enabled() {
        return url != null && url.startsWith("jdbc:postgresql:");
    }

    public String url() {
        return url;
    }

    /**
     * A new leadership claim for this server, named {@code me} to the others.
     *
     * @throws java.io.IOException when the password file cannot be read
     */
    public java.util.function.Supplier<Leadership> leads(String me, java.io.PrintStream err) throws java.io.IOException {
        String password = org.ripv.launch.Secrets.resolve(null, passwordFile, PASSWORD_ENV, "--state-db-password", false, err);
        if (checkMillis < 100) {
            throw new IllegalArgumentException("--lead-check must be at least 100 ms");
        }
        Duration check = Duration.ofMillis(checkMillis);
        Leadership.Timings t = new Leadership.Timings(check, Duration.ofSeconds(3), Duration.ofSeconds(5).plus(check),
                Duration.ofSeconds(1));
        return () -> new Leadership(url, user, password, me, t);
    }
}
