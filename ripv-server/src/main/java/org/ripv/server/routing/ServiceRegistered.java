package org.ripv.server.routing;

import java.util.Optional;
import org.ripv.messages.ErrorCode;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceRegistry;

/** Step 2: the MailBox's service is registered now. */
record ServiceRegistered(ServiceRegistry services) implements AdmissionStep {
    @Override
    public Verdict check(Admitting a) {
        Optional<ServiceReference> found = services.find(a.address().service().toString());
        if (found.isEmpty()) {
            return Verdict.refuse(a.refuse(ErrorCode.UNKNOWN_SERVICE,
                    "no service " + a.address().service() + " is registered; ?services lists those that are"));
        }
        a.service(found.get());
        return Verdict.PASS;
    }
}
