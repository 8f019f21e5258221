package org.ripv.server.http;

/**
 * Who may upload through the landing page: the same users, passwords, limits and rights as the
 * client port. Without one (the default) the page takes no uploads at all.
 */
public interface WebAccess {

    /** A log-in's outcome: the user, or why not (to show the visitor). */
    record Result(String user, String refusal) {
        public static Result ok(String user) {
            return new Result(user, null);
        }

        public static Result refused(String why) {
            return new Result(null, why);
        }
    }

    /** Checks a password from the log-in form; clears it. */
    Result login(String user, char[] password, String address);

    /** May this user store a file of this name (the permit file's rule for {@code ?upload NAME})? */
    boolean mayUpload(String user, String fileName);
}
