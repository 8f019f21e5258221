package org.ripv.server.routing;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.naming.MailboxAddress;
import org.ripv.naming.MalformedNameException;

/** Step 1: the request names a MailBox, and its address is well formed. */
final class MailboxChosen implements AdmissionStep {
    /**
     * Addresses already parsed: a server talks to a few dozen MailBoxes, and parsing one is three
     * regular expressions per request. Bounded, so that a client sending made-up addresses cannot
     * grow it; only well-formed addresses are kept.
     */
    private final Map<String, MailboxAddress> addresses = new ConcurrentHashMap<>();
    static final int MAX_ADDRESSES = 4096;

    @Override
    public Verdict check(Admitting a) {
        String text = a.request().header().mailboxAddress();
        if (text.isEmpty()) {
            return Verdict.refuse(a.refuse(ErrorCode.BAD_REQUEST, "no mailbox chosen for '" + Header.abbreviate(a.body())
                    + "': pick one (use MAILBOX); ?mailboxes lists them"));
        }
        try {
            a.address(parsed(text));
        } catch (MalformedNameException e) {
            return Verdict.refuse(a.refuse(ErrorCode.UNKNOWN_MAILBOX, e.getMessage()));
        }
        return Verdict.PASS;
    }

    private MailboxAddress parsed(String text) {
        MailboxAddress known = addresses.get(text);
        if (known != null) {
            return known;
        }
        MailboxAddress a = MailboxAddress.parse(text);
        if (addresses.size() >= MAX_ADDRESSES) {
            addresses.clear();
        }
        addresses.put(text, a);
        return a;
    }
}
