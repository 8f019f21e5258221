package org.ripv.server.routing;

import java.time.Instant;
import java.util.Map;
import org.ripv.messages.ErrorCode;
import org.ripv.server.lock.OperatorLock;

/** Step 6: nobody else holds the MailBox's operator lock ({@code ?lock}). */
record LockFree(Map<String, OperatorLock> locks) implements AdmissionStep {
    @Override
    public Verdict check(Admitting a) {
        OperatorLock lock = locks.get(a.address().toString());
        if (lock != null && !lock.expired() && !lock.user().equals(a.userName())) {
            return Verdict.refuse(a.refuse(ErrorCode.MAILBOX_LOCKED, a.address() + " is locked by " + lock.user() + " until "
                    + Instant.ofEpochMilli(lock.untilMillis()) + "; try later"));
        }
        return Verdict.PASS;
    }
}
