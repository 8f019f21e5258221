package org.ripv.service;

/**
 * Whether a MailBox's resource can take commands now, the service's word on it, and what it is
 * doing ({@code running}: e.g. "ymodem:get MISSION1.LOG 40 % ETA 1:12"; empty when idle or not told).
 */
public record Availability(boolean available, String detail, String running) {
    public Availability {
        detail = detail == null ? "" : detail;
        running = running == null ? "" : running;
    }

    public Availability(boolean available, String detail) {
        this(available, detail, "");
    }

    /** Available, and busy with {@code what} ({@code ?status} shows it in place of "available"). */
    public static Availability running(String what, String detail) {
        return new Availability(true, detail, what);
    }

    public static Availability available(String detail) {
        return new Availability(true, detail);
    }

    public static Availability notAvailable(String why) {
        return new Availability(false, why);
    }
}
