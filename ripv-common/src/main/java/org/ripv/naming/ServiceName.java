package org.ripv.naming;

import java.util.Objects;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The full name of a registered service (Appendix A, III): {@code <ServiceName>::<host>}, e.g.
 * {@code <DatabaseServer>::<deslab.mit.edu>}.
 */
public record ServiceName(String service, String host) {
    /** The grammar of a service's name and of a host (the web pages' address.js holds the same text). */
    public static final String SERVICE = "[A-Za-z][A-Za-z0-9_]{0,63}";
    public static final String HOST = "[A-Za-z0-9._:%\\-]{1,253}";
    private static final Pattern FULL = Pattern.compile("<(" + SERVICE + ")>::<(" + HOST + ")>");
    /** Compiled once: every request's address is checked against them. */
    private static final Pattern SERVICE_NAME = Pattern.compile(SERVICE);
    private static final Pattern HOST_NAME = Pattern.compile(HOST);

    public ServiceName {
        Objects.requireNonNull(service, "service");
        Objects.requireNonNull(host, "host");
        if (!SERVICE_NAME.matcher(service).matches()) {
            throw new MalformedNameException("a service name is a letter then letters, digits or _, got '" + service + "'");
        }
        if (!HOST_NAME.matcher(host).matches()) {
            throw new MalformedNameException("'" + host + "' is not a host name or address");
        }
    }

    /** Parses {@code <Service>::<host>}. */
    public static ServiceName parse(String text) {
        Matcher m = FULL.matcher(text == null ? "" : text.trim());
        if (!m.matches()) {
            throw new MalformedNameException("'" + text + "' is not a service name of the form <Service>::<host>");
        }
        return new ServiceName(m.group(1), m.group(2));
    }

    /** The MailBox of this service with the given handle. */
    public MailboxAddress mailbox(String handle) {
        return new MailboxAddress(this, handle);
    }

    @Override
    public String toString() {
        return "<" + service + ">::<" + host + ">";
    }
}
