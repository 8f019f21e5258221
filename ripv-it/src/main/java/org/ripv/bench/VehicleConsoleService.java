package org.ripv.bench;

import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.VehicleEvent;
import org.ripv.naming.MailboxAddress;
import org.ripv.service.RIPVService;
import org.ripv.service.Reply;

/**
 * A stand-in for a vehicle link that publishes console entries as the serial service does, for
 * the console tests and {@code ./ripv bench console}: {@link #line}, {@link #event} publish from
 * the caller; the MailBox answers {@code say TEXT} (published as the command and a reply line).
 */
public final class VehicleConsoleService extends RIPVService {
    public static final String SID = "100200";
    private final String handle;
    private volatile MailboxAddress address;

    public VehicleConsoleService(String host, String handle) {
        super("VehicleConsole", SID, host);
        this.handle = handle;
    }

    @Override
    protected void open() {
        address = openMailBox(handle, request -> {
            String c = request.command().trim();
            publish(ConsoleEntry.command(mailbox(), request.user(), c));
            if (c.startsWith("say ")) {
                publish(ConsoleEntry.line(mailbox(), c.substring(4)));
                return Reply.ok(c.substring(4));
            }
            return Reply.error(ErrorCode.UNKNOWN_COMMAND, "this vehicle knows only 'say TEXT'");
        });
    }

    @Override
    protected String description() {
        return "A test vehicle that publishes console entries";
    }

    /** The MailBox's full address. */
    public String mailbox() {
        return address.toString();
    }

    public void line(String text) {
        publish(ConsoleEntry.line(mailbox(), text));
    }

    public void publishEntry(ConsoleEntry e) {
        publish(e);
    }

    public void event(VehicleEvent e, String detail, Double lat, Double lon) {
        publish(ConsoleEntry.event(mailbox(), e, detail, lat, lon));
    }
}
