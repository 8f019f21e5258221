package org.ripv.naming;

import java.util.Objects;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A MailBox's address (Appendix A, IV): the full service name followed by a communications
 * handle, e.g. {@code <SerialPortServer>::<imvros.mit.edu>COM1}.
 */
public record MailboxAddress(ServiceName service, String handle) {
    /** The handle's grammar (the web pages' address.js holds the same text). */
    public static final String HANDLE = "[A-Za-z0-9][A-Za-z0-9._\\-]{0,127}";
    private static final Pattern FULL = Pattern.compile(
            "<(" + ServiceName.SERVICE + ")>::<(" + ServiceName.HOST + ")>(" + HANDLE + ")");
    private static final Pattern HANDLE_ONLY = Pattern.compile(HANDLE);

    public MailboxAddress {
        Objects.requireNonNull(service, "service");
        if (handle == null || !HANDLE_ONLY.matcher(handle).matches()) {
            throw new MalformedNameException("a mailbox handle is letters, digits, '.', '_' or '-', got '" + handle + "'");
        }
    }

    /** Parses {@code <Service>::<host>HANDLE}. */
    public static MailboxAddress parse(String text) {
        Matcher m = FULL.matcher(text == null ? "" : text.trim());
        if (!m.matches()) {
            throw new MalformedNameException("'" + text
                    + "' is not a mailbox address of the form <Service>::<host>HANDLE, e.g. <SerialPortServer>::<localhost>ttyS0");
        }
        return new MailboxAddress(new ServiceName(m.group(1), m.group(2)), m.group(3));
    }

    @Override
    public String toString() {
        return service + handle;
    }
}
