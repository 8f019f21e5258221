package org.ripv.server.plans;

import org.ripv.messages.IncomingServerMessage;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.session.Rights;

/**
 * The rights {@code ?plan} and {@code ?changes} check: reading a MailBox, and changing a
 * vehicle's plan (a permit rule allowing the command on RIPVServer). A refusal throws
 * {@link PlanCommands.Refused}, answered FORBIDDEN.
 */
record PlanRights(PlanHost host) {
    void mayRead(String user, String mailbox) {
        String why = Rights.whyNotRead(host.permits(), user, mailbox);
        if (why != null) {
            throw new PlanCommands.Refused(why);
        }
    }

    PermitFile.User permitted(IncomingServerMessage request) {
        String user = request.header().origin().user();
        PermitFile p = host.permits();
        PermitFile.User u = p.user(user).orElseThrow(() -> new PlanCommands.Refused("user '" + user + "' is no longer in the permit file"));
        PermitFile.Decision d = p.decide(u, PlanCommands.SERVER, "", request.header().body().trim());
        if (!d.allowed()) {
            throw new PlanCommands.Refused("user '" + user + "' may not change a vehicle's plan (" + d.because() + ")");
        }
        return u;
    }
}
