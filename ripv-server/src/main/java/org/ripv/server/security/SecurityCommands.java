package org.ripv.server.security;

import java.util.List;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;

/**
 * The admin's log-in commands (the permit file decides who is an admin: a rule must allow the
 * command for {@code RIPVServer}): {@code ?logins} lists failures and blocks,
 * {@code ?unlock-login USER|ADDRESS} lifts one.
 */
public final class SecurityCommands {
    private SecurityCommands() {}

    /** Runs {@code ?logins} or {@code ?unlock-login}; the caller has checked the user's right. */
    public static OutgoingServerMessage run(IncomingServerMessage request, String fid, String[] w, LoginThrottle throttle) {
        String admin = request.header().origin().user();
        if (w[0].equalsIgnoreCase("?logins")) {
            List<String> lines = throttle.describe();
            return ok(request, fid, lines.isEmpty() ? "no failed log-ins"
                    : lines.size() + " user(s) or address(es) with failed log-ins\n" + String.join("\n", lines));
        }
        if (w.length != 2) {
            throw new IllegalArgumentException("usage: ?unlock-login USER|ADDRESS");
        }
        boolean lifted = throttle.lift(w[1]);
        Audit.log(false, "login-unlocked", "who", w[1], "by", admin, "had-failures", lifted);
        return ok(request, fid, lifted ? "lifted the log-in block of " + w[1] : "no failed log-ins recorded for " + w[1]);
    }

    private static OutgoingServerMessage ok(IncomingServerMessage request, String fid, String text) {
        return request.reply(Footer.ok(fid, text, null).via("RIPVServer"));
    }
}
