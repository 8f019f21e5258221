package org.ripv.services.database;

import java.util.Objects;

/**
 * One database the DatabaseServer serves through one MailBox: how to connect as the owner (who
 * may change data) and, optionally, as a read-only reader.
 *
 * @param handle         the MailBox handle (Appendix A), e.g. {@code TTY1}
 * @param driver         a JDBC driver class to load first, or null to rely on the driver's
 *                       automatic registration
 * @param url            the JDBC URL, e.g. {@code jdbc:postgresql://db.example.org/ripv}
 * @param user           the owner's database user, or null for none
 * @param password       the owner's password, or null
 * @param readerUser     a database user that holds only SELECT grants (and is read-only in the
 *                       database itself), used for RIPV users with the {@code db-reader} role;
 *                       null when there is none, and then such users are refused
 * @param readerPassword the reader's password, or null
 * @param schema         the schema the reader's unqualified table names resolve to (the owner's
 *                       schema), or null to leave the database's default
 */
public record DatabaseTarget(String handle, String driver, String url, String user, String password,
                             String readerUser, String readerPassword, String schema) {
    public DatabaseTarget {
        Objects.requireNonNull(handle, "handle");
        if (url == null || !url.startsWith("jdbc:")) {
            throw new IllegalArgumentException("a JDBC URL starts with 'jdbc:', got '" + url + "'");
        }
    }

    /** A target without a reader. */
    public static DatabaseTarget of(String handle, String url, String user, String password) {
        return new DatabaseTarget(handle, null, url, user, password, null, null, null);
    }

    public boolean hasReader() {
        return readerUser != null && !readerUser.isBlank();
    }

    /** True for an embedded Derby URL, which the service shuts down when it stops. */
    public boolean embeddedDerby() {
        return url.startsWith("jdbc:derby:") && !url.startsWith("jdbc:derby://");
    }

    /** The URL without anything after {@code ;} or {@code ?} (where passwords may hide), for logs and ?status. */
    public String safeUrl() {
        int cut = url.length();
        for (char c : new char[] {';', '?'}) {
            int i = url.indexOf(c);
            if (i >= 0 && i < cut) {
                cut = i;
            }
        }
        return url.substring(0, cut);
    }

    @Override
    public String toString() {
        return handle + " " + safeUrl() + (user == null ? "" : " as " + user) + (hasReader() ? " (reader " + readerUser + ")" : "");
    }
}
