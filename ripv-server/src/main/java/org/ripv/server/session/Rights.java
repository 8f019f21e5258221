package org.ripv.server.session;

import org.ripv.naming.MailboxAddress;
import org.ripv.server.permit.PermitFile;

/**
 * The read right on a MailBox, which watching, {@code ?history} and notifications need
 * (docs/permit.md): the permit file must allow the pseudo-command {@code ?read} for the user in
 * that MailBox's service and handle, like any command. Sending keeps its per-command check.
 */
public final class Rights {
    /** The command the permit file's rules are asked about for reading a MailBox. */
    public static final String READ = "?read";

    private Rights() {}

    /** Null when the user may read the MailBox, else why not. */
    public static String whyNotRead(PermitFile permits, String user, String mailbox) {
        MailboxAddress address;
        try {
            address = MailboxAddress.parse(mailbox);
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
        PermitFile.User u = permits.user(user).orElse(null);
        if (u == null) {
            return "user '" + user + "' is no longer in the permit file";
        }
        PermitFile.Decision d = permits.decide(u, address.service().service(), address.handle(), READ);
        return d.allowed() ? null : "user '" + user + "' may not read " + mailbox + " (" + d.because() + ")";
    }

    public static boolean mayRead(PermitFile permits, String user, String mailbox) {
        return whyNotRead(permits, user, mailbox) == null;
    }
}
