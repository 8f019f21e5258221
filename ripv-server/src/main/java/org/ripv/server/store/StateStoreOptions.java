package org.ripv.server.store;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import org.ripv.launch.Secrets;
import picocli.CommandLine.Option;

/** The {@code ripv server} options that choose the state store (a picocli mixin). */
public final class StateStoreOptions {
    @Option(names = "--state-db", paramLabel = "JDBC-URL",
            description = "Keep transcripts, workflow queues and receipts, subscriptions and the audit trail in this PostgreSQL"
                    + " database (jdbc:postgresql://HOST:PORT/DATABASE) instead of files in the data directory;"
                    + " a standby server can share it. Tables are made on first use.")
    String url;
    @Option(names = "--state-db-user", paramLabel = "USER", description = "Its user (default $RIPV_STATE_DB_USER).")
    String user;
    @Option(names = "--state-db-password-file", paramLabel = "FILE",
            description = "File holding its password (else $RIPV_STATE_DB_PASSWORD, else the terminal asks).")
    Path passwordFile;

    /** Where the state goes; reads the password from its file, the environment or the terminal. */
    public StoreLocation location(PrintStream err) throws IOException {
        if (url == null) {
            if (user != null || passwordFile != null) {
                throw new IllegalArgumentException("--state-db-user and --state-db-password-file need --state-db JDBC-URL");
            }
            return StoreLocation.embedded();
        }
        String u = user != null ? user : System.getenv("RIPV_STATE_DB_USER");
        String pw;
        try {
            pw = Secrets.resolve(null, passwordFile, "RIPV_STATE_DB_PASSWORD", "--state-db-password",
                    u != null && !u.isEmpty(), err);
        } catch (IOException e) {
            throw new IOException("cannot read --state-db-password-file " + passwordFile + ": " + e, e);
        }
        return new StoreLocation(url, u == null || u.isEmpty() ? null : u, pw);
    }
}
