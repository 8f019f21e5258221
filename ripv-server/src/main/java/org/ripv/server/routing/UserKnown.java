package org.ripv.server.routing;

import java.util.Optional;
import java.util.function.Supplier;
import org.ripv.messages.ErrorCode;
import org.ripv.server.permit.PermitFile;

/** Step 4: the sender is still in the permit file (a user removed since log-in sends nothing more). */
record UserKnown(Supplier<PermitFile> permits) implements AdmissionStep {
    @Override
    public Verdict check(Admitting a) {
        Optional<PermitFile.User> user = permits.get().user(a.userName());
        if (user.isEmpty()) {
            return Verdict.refuse(a.refuse(ErrorCode.FORBIDDEN, "user '" + a.userName() + "' is no longer in the permit file"));
        }
        a.user(user.get());
        return Verdict.PASS;
    }
}
