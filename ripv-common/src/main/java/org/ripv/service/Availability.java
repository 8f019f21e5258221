package org.ripv.service;

/** Whether a MailBox's resource can take commands now, and the service's word on it. */
public record Availability(boolean available, String detail) {
    public static Availability available(String detail) {
        return new Availability(true, detail);
    }

    public static Availability notAvailable(String why) {
        return new Availability(false, why);
    }
}
