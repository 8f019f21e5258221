package org.ripv.server.routing;

import java.util.function.Supplier;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.server.permit.PermitFile;

/** Step 5: the permit file's rules let this user send this command to this MailBox (docs/permit.md). */
record PermitAllows(Supplier<PermitFile> permits) implements AdmissionStep {
    @Override
    public Verdict check(Admitting a) {
        PermitFile.Decision d = permits.get().decide(a.user(), a.address().service().service(), a.address().handle(), a.body());
        if (!d.allowed()) {
            return Verdict.refuse(a.refuse(ErrorCode.FORBIDDEN, "user '" + a.userName() + "' may not send '"
                    + Header.abbreviate(a.body().trim()) + "' to " + a.address() + " (" + d.because() + ")"));
        }
        return Verdict.PASS;
    }
}
