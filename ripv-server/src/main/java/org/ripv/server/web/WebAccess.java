package org.ripv.server.web;

import java.util.List;

/**
 * Who may log in on the web console and upload: the client port's users, PBKDF2, throttle and
 * audit (implemented by {@code org.ripv.server.security.WebLogins}).
 */
public interface WebAccess {

    /** A log-in's outcome: the user and their roles, or why not (to show the visitor). */
    record Result(String user, List<String> roles, String refusal) {
        public static Result ok(String user, List<String> roles) {
            return new Result(user, List.copyOf(roles), null);
        }

        public static Result refused(String why) {
            return new Result(null, List.of(), why);
        }
    }

    /** Checks a password from the log-in form, throttled by the browser's address; clears it. */
    Result login(String user, char[] password, String address);

    /** May this user store a file of this name (the permit file's rule for {@code ?upload NAME})? */
    boolean mayUpload(String user, String fileName);
}
