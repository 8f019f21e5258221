package org.ripv.messages;

/**
 * One MailBox as the operator sees it ({@code ?status}, {@code ?mailboxes}).
 *
 * @param address   its full address, {@code <SerialPortServer>::<host>ttyS0}
 * @param available whether it can take commands now (a glider under water is not)
 * @param detail    the service's word on why, or what the resource is
 * @param busy      whether a command is running in it right now
 * @param lockedBy  the user holding the operator lock, or empty
 * @param session   the vehicle's call state as the server derived it from console events, or null
 *                  when the MailBox has published none (added with the live console; older peers
 *                  read it as null)
 * @param running   what the MailBox is doing now, as its service says ("ymodem:get MISSION1.LOG 40 %
 *                  ETA 1:12"), or empty (added with issue 12; older peers read it as empty)
 */
public record MailboxStatus(String address, boolean available, String detail, boolean busy, String lockedBy,
                            SessionState session, String running)
        implements Result {
    public MailboxStatus {
        detail = detail == null ? "" : detail;
        lockedBy = lockedBy == null ? "" : lockedBy;
        running = running == null ? "" : running;
    }

    public MailboxStatus(String address, boolean available, String detail, boolean busy, String lockedBy,
                         SessionState session) {
        this(address, available, detail, busy, lockedBy, session, "");
    }

    /** A status without session state (what services report). */
    public MailboxStatus(String address, boolean available, String detail, boolean busy, String lockedBy) {
        this(address, available, detail, busy, lockedBy, null);
    }

    public MailboxStatus withLock(String holder) {
        return new MailboxStatus(address, available, detail, busy, holder, session, running);
    }

    public MailboxStatus withSession(SessionState state) {
        return new MailboxStatus(address, available, detail, busy, lockedBy, state, running);
    }
}
