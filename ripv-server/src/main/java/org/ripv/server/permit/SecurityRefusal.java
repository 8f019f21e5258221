package org.ripv.server.permit;

/** A request the permit file refuses: answered FORBIDDEN with this message, which quotes the rule that decided. */
public final class SecurityRefusal extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    public SecurityRefusal(String message) {
        super(message);
    }
}
