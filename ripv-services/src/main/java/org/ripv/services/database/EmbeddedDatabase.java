package org.ripv.services.database;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.Base64;
import java.util.Comparator;
import java.util.List;
import java.util.Properties;
import java.util.stream.Stream;
import org.ripv.files.PrivateFiles;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The DatabaseServer's default database: embedded Apache Derby (Cloudscape's descendant, the
 * database of the thesis) in the service's data directory, created from {@code vehicleDB.sql}
 * and {@code sample-data.sql} on first start and reused afterwards.
 *
 * <p>Read-only users are read-only in the database itself. The database is created with
 * Derby NATIVE authentication and SQL authorization, two users and these properties:
 * <ul>
 *   <li>{@code RIPV} — the database owner; owns the tables; full access;</li>
 *   <li>{@code READER} — holds only {@code SELECT} grants on the six tables, and is listed in
 *       {@code derby.database.readOnlyAccessUsers}, so it cannot create tables in its own
 *       schema either;</li>
 *   <li>{@code derby.database.defaultConnectionMode=noAccess}: no other user may connect.</li>
 * </ul>
 * Their random passwords are in {@code DATA/credentials.properties} (owner-only permissions),
 * written last, so a directory without it is a first start that did not finish and is
 * created again.
 */
public final class EmbeddedDatabase {
    private static final Logger log = LoggerFactory.getLogger(EmbeddedDatabase.class);

    /** The database owner (Derby DBO). */
    public static final String OWNER = "RIPV";
    /** The read-only user. */
    public static final String READER = "READER";
    /** The tables of {@code vehicleDB.sql}. */
    public static final List<String> TABLES = List.of("VEHICLE", "MISSION", "LEG", "VEHICLE_DATA", "SENSOR", "SENSOR_DATA");

    static final String DATABASE_DIR = "vehicledb";
    static final String CREDENTIALS = "credentials.properties";

    private EmbeddedDatabase() {}

    /**
     * Opens the embedded database in {@code dataDir}, creating and seeding it on first start.
     *
     * @param handle the MailBox handle to serve it under
     * @return how to connect to it as owner and as reader
     */
    public static DatabaseTarget prepare(Path dataDir, String handle) throws IOException, SQLException {
        PrivateFiles.createDirectories(dataDir);
        PrivateFiles.restrict(dataDir);
        if (System.getProperty("derby.storage.useDefaultFilePermissions") == null) {
            // Derby's files readable by their owner only (Derby's default outside its network server is the umask's)
            System.setProperty("derby.storage.useDefaultFilePermissions", "false");
        }
        if (System.getProperty("derby.stream.error.file") == null) {
            // Derby writes derby.log into the working directory unless told otherwise.
            System.setProperty("derby.stream.error.file", dataDir.resolve("derby.log").toString());
        }
        Path db = dataDir.resolve(DATABASE_DIR).toAbsolutePath();
        Path credentials = dataDir.resolve(CREDENTIALS);
        String url = "jdbc:derby:" + db;
        if (Files.isDirectory(db) && Files.isRegularFile(credentials)) {
            Properties p = new Properties();
            try (Reader r = Files.newBufferedReader(credentials, StandardCharsets.UTF_8)) {
                p.load(r);
            }
            String ownerPassword = require(p, "owner.password", credentials);
            checkOpens(url, ownerPassword, db);
            restrictTree(dataDir);
            log.info("reusing the vehicle database in {}", db);
            return target(handle, url, ownerPassword, require(p, "reader.password", credentials));
        }
        if (Files.exists(db)) {
            log.warn("{} has no {}: its first start did not finish; creating it again", db, CREDENTIALS);
            deleteTree(db);
        }
        if (SeedInChild.wanted() && SeedInChild.run(dataDir, handle)) {
            return prepare(dataDir, handle); // made by a JVM of its own (first start in seconds): reuse it
        }
        String ownerPassword = randomPassword();
        String readerPassword = randomPassword();
        long started = System.nanoTime();
        try {
            install(url, ownerPassword, readerPassword, true);
        } catch (SQLException | IOException | RuntimeException e) {
            shutdownQuietly(url, ownerPassword);
            deleteTree(db);
            throw e;
        }
        writeCredentials(credentials, ownerPassword, readerPassword);
        restrictTree(dataDir);
        log.info("created and seeded the vehicle database in {} in {} ms", db, (System.nanoTime() - started) / 1_000_000);
        return target(handle, url, ownerPassword, readerPassword);
    }

    /** Boots the database once, so a database another process holds fails the start with a clear message. */
    private static void checkOpens(String url, String ownerPassword, Path db) throws SQLException {
        try (Connection c = DriverManager.getConnection(url, OWNER, ownerPassword)) {
            c.getMetaData(); // booted and authenticated
        } catch (SQLException e) {
            for (SQLException x = e; x != null; x = x.getNextException()) {
                if ("XSDB6".equals(x.getSQLState())) {
                    throw new SQLException("the vehicle database in " + db + " is open in another process (another"
                            + " DatabaseServer, or Derby's ij); stop it or give this one another --data", "XSDB6", e);
                }
            }
            throw new SQLException("cannot open the vehicle database in " + db + ": " + DatabaseHandler.describe(e),
                    e.getSQLState(), e);
        }
    }

    private static DatabaseTarget target(String handle, String url, String ownerPassword, String readerPassword) {
        return new DatabaseTarget(handle, null, url, OWNER, ownerPassword, READER, readerPassword, OWNER);
    }

    /**
     * Creates a Derby database at {@code url} (embedded, {@code memory:}, or a network server's
     * {@code jdbc:derby://host:port/name}) with the RIPV schema, optionally the sample data, and
     * the owner and reader users described above. The database must not exist yet.
     */
    public static void install(String url, String ownerPassword, String readerPassword, boolean sampleData)
            throws SQLException, IOException {
        try (Connection c = DriverManager.getConnection(url + ";create=true", OWNER, ownerPassword)) {
            try (Statement st = c.createStatement()) {
                // The DBO's credentials must come first. Storing them turns on NATIVE::LOCAL
                // authentication by itself (Derby sets derby.authentication.provider); it starts
                // at the next boot.
                st.execute("CALL SYSCS_UTIL.SYSCS_CREATE_USER('" + OWNER + "', " + literal(ownerPassword) + ")");
                st.execute("CALL SYSCS_UTIL.SYSCS_CREATE_USER('" + READER + "', " + literal(readerPassword) + ")");
                setProperty(st, "derby.database.sqlAuthorization", "true");
                setProperty(st, "derby.database.defaultConnectionMode", "noAccess");
                setProperty(st, "derby.database.fullAccessUsers", OWNER);
                setProperty(st, "derby.database.readOnlyAccessUsers", READER);
            }
            c.setAutoCommit(false);
            SqlScript.run(c, SqlScript.resource("vehicleDB.sql"), "vehicleDB.sql");
            if (sampleData) {
                SeedLoader.run(c, SqlScript.resource("sample-data.sql"), "sample-data.sql");
            }
            c.commit();
        }
        // GRANT needs SQL authorization, which a property set above turns on only after a reboot.
        shutdown(url, ownerPassword);
        try (Connection c = DriverManager.getConnection(url, OWNER, ownerPassword);
             Statement st = c.createStatement()) {
            for (String table : TABLES) {
                st.execute("GRANT SELECT ON " + table + " TO " + READER);
            }
        }
    }

    private static String literal(String s) {
        return "'" + s.replace("'", "''") + "'";
    }

    private static void setProperty(Statement st, String key, String value) throws SQLException {
        st.execute("CALL SYSCS_UTIL.SYSCS_SET_DATABASE_PROPERTY('" + key + "', '" + value + "')");
    }

    /** Shuts a Derby database down (releases its files and locks). */
    public static void shutdown(String url, String ownerPassword) throws SQLException {
        shutdown(url, OWNER, ownerPassword);
    }

    /** Shuts a Derby database down as the given user. */
    public static void shutdown(String url, String user, String password) throws SQLException {
        try {
            DriverManager.getConnection(url + ";shutdown=true", user, password).close();
        } catch (SQLException e) {
            // Derby reports a clean single-database shutdown as SQLState 08006.
            if (!"08006".equals(e.getSQLState())) {
                throw e;
            }
        }
    }

    static void shutdownQuietly(String url, String ownerPassword) {
        shutdownQuietly(url, OWNER, ownerPassword);
    }

    static void shutdownQuietly(String url, String user, String password) {
        try {
            shutdown(url, user, password);
        } catch (SQLException e) {
            log.debug("shutdown of {} failed: {}", url, e.getMessage());
        }
    }

    private static String require(Properties p, String key, Path file) throws IOException {
        String v = p.getProperty(key);
        if (v == null || v.isBlank()) {
            throw new IOException(file + " has no " + key + "; remove the data directory's " + DATABASE_DIR
                    + " and " + CREDENTIALS + " to create the database again");
        }
        return v;
    }

    private static void writeCredentials(Path file, String ownerPassword, String readerPassword) throws IOException {
        Properties p = new Properties();
        p.setProperty("owner.user", OWNER);
        p.setProperty("owner.password", ownerPassword);
        p.setProperty("reader.user", READER);
        p.setProperty("reader.password", readerPassword);
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        Files.deleteIfExists(tmp);
        if (FileSystems.getDefault().supportedFileAttributeViews().contains("posix")) {
            Files.createFile(tmp, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        }
        try (Writer w = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8)) {
            p.store(w, "RIPV DatabaseServer: the embedded database's users (keep private)");
        }
        Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    private static String randomPassword() {
        byte[] b = new byte[18];
        new SecureRandom().nextBytes(b);
        return Base64.getUrlEncoder().withoutPadding().encodeToString(b);
    }

    /** Makes every file and directory under {@code dir} owner-only (a database made by an older version, derby.log). */
    static void restrictTree(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (!Files.isSymbolicLink(p)) {
                    PrivateFiles.restrict(p);
                }
            }
        }
    }

    private static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) {
            return;
        }
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }
}
