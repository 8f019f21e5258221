package org.ripv.services.database;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import org.ripv.dac.DacException;
import org.ripv.dac.delivery.Deliveries;
import org.ripv.launch.Secrets;
import org.ripv.service.ServiceLaunchOptions;
import org.ripv.launch.Launchers;
import org.ripv.services.ingest.IngestLimits;
import picocli.CommandLine;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * Launches a {@link DatabaseServer} and keeps it registered with a RIPVServer (SPEC §11):
 * <pre>
 * ./ripv service database --server HOST[:REGPORT] [--secret-file F] [--data DIR]
 *                         [--driver CLASS] --url JDBC_URL [--db-user U --db-password P] [--reader-user R ...] ...
 *                         [--max-rows N] [--query-timeout S]
 * java -jar ripv-services.jar DatabaseServer //host [&lt;driver&gt; &lt;url&gt;]      (the thesis form)
 * </pre>
 * With no {@code --url} the service opens embedded Derby in {@code --data} (created and seeded on
 * first start). Each {@code --url} (with the options that follow it) is one database and one
 * MailBox: TTY1, TTY2, ... in order.
 *
 * <p>Exit codes: 0 stopped normally, 1 could not start (database or server settings), 2 usage.
 */
@Command(name = "database", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Runs the DatabaseServer (SID 666666): SQL to embedded Derby or any JDBC database.",
                "With no --url: embedded Derby in --data, created from sql/vehicleDB.sql and sql/sample-data.sql "
                        + "on first start. Users with the permit-file role 'db-reader' use the read-only database user."})
public final class DatabaseServerCommand implements Callable<Integer> {
    @Mixin
    ServiceLaunchOptions launch;

    @ArgGroup(exclusive = false, multiplicity = "0..*", heading = "A database (repeat for several; one MailBox each):%n")
    List<Database> databases = new ArrayList<>();

    @Option(names = "--data", paramLabel = "DIR",
            description = "Directory of the embedded Derby database (default: ~/.ripv/services/database).")
    Path data;

    @Option(names = "--max-rows", paramLabel = "N", defaultValue = "" + QueryLimits.DEFAULT_MAX_ROWS,
            description = "Rows a query returns at most; more are cut and marked truncated (default: ${DEFAULT-VALUE}).")
    int maxRows;

    @Option(names = "--query-timeout", paramLabel = "SECONDS", defaultValue = "" + QueryLimits.DEFAULT_QUERY_TIMEOUT_SECONDS,
            description = "Seconds a statement may run before the database cancels it; 0 for no limit (default: ${DEFAULT-VALUE}).")
    int queryTimeout;

    @Option(names = "--max-result-chars", paramLabel = "N", defaultValue = "" + QueryLimits.DEFAULT_MAX_RESULT_CHARS,
            description = "Characters of cell text one reply may carry; keeps a table inside one 16 MiB frame (default: ${DEFAULT-VALUE}).")
    long maxResultChars;

    @Option(names = "--ingest-max-bytes", paramLabel = "BYTES", defaultValue = "" + IngestLimits.DEFAULT_MAX_PLAIN_BYTES,
            description = "Bytes one compressed Slocum file may decompress to; a larger one is refused (default: ${DEFAULT-VALUE}).")
    long ingestMaxBytes;

    @Option(names = "--ingest-max-rows", paramLabel = "N", defaultValue = "" + IngestLimits.DEFAULT_MAX_ROWS,
            description = "Rows (cycles) one ingested file may hold; a larger one is refused, nothing of it stored (default: ${DEFAULT-VALUE}).")
    long ingestMaxRows;

    @Option(names = "--dac", paramLabel = "FILE",
            description = "A DAC deployment (JSON: glider, metadata, qc, destination …, docs/dac.md): its glider's Slocum files become"
                    + " IOOS DAC profile files as they are ingested, checked and pushed. Repeat for more gliders.")
    List<Path> dac = new ArrayList<>();

    /** One database's connection settings. */
    static final class Database {
        @Option(names = "--driver", paramLabel = "CLASS",
                description = "JDBC driver class to load (optional with JDBC 4 drivers), e.g. org.postgresql.Driver.")
        String driver;

        @Option(names = "--url", required = true, paramLabel = "JDBC_URL",
                description = "e.g. jdbc:derby://dbhost:1527/vehicledb or jdbc:postgresql://dbhost/ripv")
        String url;

        @Option(names = "--db-user", paramLabel = "U", description = "Database user for full access.")
        String user;

        @Option(names = "--db-password", paramLabel = "P", description = "Its password (visible in ps, so it warns; prefer --db-password-file, $RIPV_DB_PASSWORD or the prompt).")
        String password;

        @Option(names = "--db-password-file", paramLabel = "FILE", description = "File holding the password.")
        Path passwordFile;

        @Option(names = "--reader-user", paramLabel = "R",
                description = "Read-only database user for RIPV users with the 'db-reader' role (none: such users are refused).")
        String readerUser;

        @Option(names = "--reader-password", paramLabel = "P", description = "The reader's password (visible in ps, so it warns; prefer --reader-password-file, $RIPV_READER_PASSWORD or the prompt).")
        String readerPassword;

        @Option(names = "--reader-password-file", paramLabel = "FILE", description = "File holding the reader's password.")
        Path readerPasswordFile;

        @Option(names = "--schema", paramLabel = "SCHEMA",
                description = "Schema the reader's unqualified table names resolve to (the owner's schema).")
        String schema;
    }

    /** The default directory of the embedded database. */
    public static Path defaultDataDir() {
        String env = System.getenv("RIPV_DATABASE_DATA");
        if (env != null && !env.isBlank()) {
            return Path.of(env);
        }
        return Path.of(System.getProperty("user.home"), ".ripv", "services", "database");
    }

    /** Builds the service from the parsed options (opens or creates the embedded database when no --url was given). */
    DatabaseServer build(String host) throws Exception {
        QueryLimits limits = new QueryLimits(maxRows, queryTimeout, maxResultChars);
        List<DatabaseTarget> targets = new ArrayList<>();
        if (databases.isEmpty()) {
            targets.add(EmbeddedDatabase.prepare(data == null ? defaultDataDir() : data, DatabaseServer.handles(1).get(0)));
        } else {
            List<String> handles = DatabaseServer.handles(databases.size());
            for (int i = 0; i < databases.size(); i++) {
                Database d = databases.get(i);
                targets.add(new DatabaseTarget(handles.get(i), d.driver, d.url, d.user,
                        secret(d.password, d.passwordFile, d.user, "--db-password", "RIPV_DB_PASSWORD"), d.readerUser,
                        secret(d.readerPassword, d.readerPasswordFile, d.readerUser, "--reader-password", "RIPV_READER_PASSWORD"),
                        d.schema));
            }
        }
        return new DatabaseServer(host, targets, limits).withIngestLimits(new IngestLimits(ingestMaxBytes,
                ingestMaxRows));
    }

    /** The DAC deployments of {@code --dac}, read and checked before the service registers. */
    Deliveries deliveries() throws DacException, IOException {
        return dac.isEmpty() ? Deliveries.NONE : Deliveries.start(dac);
    }

    /** Where launch warnings go (standard error; injectable for tests). */
    PrintStream err = System.err;

    /** A password from the option (with a warning), its file, the environment, or the terminal when a user is named. */
    private String secret(String value, Path file, String user, String option, String env) throws IOException {
        return Secrets.resolve(value, file, env, option, user != null, err);
    }

    @Override
    public Integer call() throws Exception {
        String host = launch.hostName();
        Deliveries deliveries;
        try {
            deliveries = deliveries();
        } catch (DacException | IOException e) {
            System.err.println("Error: the DAC deployment is refused: " + e.getMessage());
            return 1;
        }
        DatabaseServer service;
        try {
            service = build(host).withDeliveries(deliveries);
        } catch (Exception e) {
            deliveries.close();
            System.err.println("Error: cannot open the database: " + e.getMessage());
            return 1;
        }
        for (var d : deliveries.all()) {
            System.out.println("DAC deployment of " + d.deployment().glider() + " -> " + d.deployment().where()
                    + " (folder " + d.deployment().folder() + ")");
        }
        for (DatabaseTarget t : service.targets()) {
            System.out.println(service.name() + t.handle() + " -> " + t.safeUrl());
        }
        try {
            return launch.serve(service); // stopping the service shuts embedded Derby down cleanly
        } catch (IOException | IllegalArgumentException e) {
            service.stop();
            System.err.println("Error: " + e.getMessage());
            return 1;
        }
    }

    /**
     * Rewrites the thesis form {@code //host [<driver> <url>]} (or {@code //host <url>}) into
     * options; other argument lists are returned unchanged.
     */
    public static String[] thesisArgs(String[] args) {
        if (args.length == 0 || !args[0].startsWith("//")) {
            return args;
        }
        List<String> out = new ArrayList<>(List.of("--server", args[0]));
        int rest = 1;
        if (args.length >= 3 && !args[1].startsWith("-") && args[2].startsWith("jdbc:")) {
            out.addAll(List.of("--driver", args[1], "--url", args[2]));
            rest = 3;
        } else if (args.length >= 2 && args[1].startsWith("jdbc:")) {
            out.addAll(List.of("--url", args[1]));
            rest = 2;
        }
        out.addAll(Arrays.asList(args).subList(rest, args.length));
        return out.toArray(String[]::new);
    }

    /** Runs the command with the given arguments (either form) and returns its exit code. */
    public static int run(String... args) {
        return Launchers.commandLine(new DatabaseServerCommand()).execute(thesisArgs(args));
    }

    public static void main(String[] args) {
        System.exit(run(args));
    }
}
