package org.ripv.naming;

/** A service name or mailbox address that does not follow Appendix A. */
public class MalformedNameException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    public MalformedNameException(String message) {
        super(message);
    }
}
