package org.ripv.server.store;

/**
 * Which store the server keeps its state in: embedded (files in the data directory; a null URL)
 * or a PostgreSQL database by JDBC URL, with its user and password.
 *
 * @param jdbcUrl  {@code jdbc:postgresql://HOST[:PORT]/DATABASE[?currentSchema=S]}, or null for embedded
 * @param user     the database user, or null for the driver's default
 * @param password its password, or null
 */
public record StoreLocation(String jdbcUrl, String user, String password) {
    public StoreLocation {
        if (jdbcUrl != null && !jdbcUrl.startsWith("jdbc:postgresql:")) {
            throw new IllegalArgumentException("--state-db takes a PostgreSQL JDBC URL (jdbc:postgresql://HOST:PORT/DATABASE), not '"
                    + PostgresStateStore.withoutSecrets(jdbcUrl) + "'");
        }
    }

    /** Files in the data directory (the default). */
    public static StoreLocation embedded() {
        return new StoreLocation(null, null, null);
    }

    public boolean isEmbedded() {
        return jdbcUrl == null;
    }

    /** Never shows the password. */
    @Override
    public String toString() {
        return isEmbedded() ? "embedded" : PostgresStateStore.withoutSecrets(jdbcUrl) + (user == null ? "" : " as " + user);
    }
}
