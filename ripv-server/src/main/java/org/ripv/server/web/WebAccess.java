package org.ripv.server.web;

import java.util.List;
import java.util.Map;

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

    /**
     * What the permit file lets a user send, for pages that show only the controls the user may use
     * (the server decides every command again when it is sent).
     *
     * @param send     whether some command may go to the MailBox at all (a command line is worth showing)
     * @param commands each command asked about, allowed or not
     */
    record Rights(boolean send, Map<String, Boolean> commands) {}

    /**
     * The user's rights on a MailBox ({@code ""}: the server's own commands, {@code ?lock ...}), for
     * these commands as the page would send them ({@code ?key ctrl-c} to a MailBox is asked as
     * {@code ?key ctrl-c}). An unknown user or a malformed address has no rights.
     */
    Rights rights(String user, String mailbox, List<String> commands);
}
