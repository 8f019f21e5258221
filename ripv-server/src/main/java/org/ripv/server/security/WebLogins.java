package org.ripv.server.security;

import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.web.WebAccess;

/**
 * The web console's log-in (and its upload form with {@code --http-upload}): the client port's users, limits, pool and
 * audit, and the permit file's rule for {@code ?upload NAME} on {@code RIPVServer}.
 */
public final class WebLogins implements WebAccess {
    private final Logins logins;
    private final Supplier<PermitFile> permits;

    public WebLogins(Logins logins, Supplier<PermitFile> permits) {
        this.logins = logins;
        this.permits = permits;
    }

    @Override
    public Result login(String user, char[] password, String address) {
        if (user.isEmpty() || user.length() > 64) {
            Arrays.fill(password, '\0');
            return Result.refused("wrong user name or password");
        }
        Logins.Check c = logins.check(user, password, address, "web");
        if (c.busy() != null) {
            return Result.refused(c.busy());
        }
        if (c.user() == null) {
            return Result.refused(c.block() != null ? "wrong user name or password, or " + Logins.refusalText(c.block())
                    : "wrong user name or password");
        }
        Audit.log(false, "login", "user", user, "from", address, "via", "web");
        return Result.ok(user, c.user().roles());
    }

    @Override
    public boolean mayUpload(String user, String fileName) {
        PermitFile p = permits.get();
        return p.user(user).map(u -> p.decide(u, "RIPVServer", "", "?upload " + fileName + " 0 0").allowed()).orElse(false);
    }

    @Override
    public Rights rights(String user, String mailbox, List<String> commands) {
        PermitFile p = permits.get();
        Map<String, Boolean> each = new LinkedHashMap<>();
        PermitFile.User u = p.user(user).orElse(null);
        String service = "RIPVServer";
        String handle = "";
        if (u != null && !mailbox.isEmpty()) {
            try {
                MailboxAddress a = MailboxAddress.parse(mailbox);
                service = a.service().service();
                handle = a.handle();
            } catch (IllegalArgumentException e) {
                u = null; // no rights on a name that is no MailBox
            }
        }
        for (String c : commands) {
            each.put(c, u != null && p.decide(u, service, handle, c).allowed());
        }
        return new Rights(u != null && p.maySendSomething(u, service, handle), each);
    }
}
