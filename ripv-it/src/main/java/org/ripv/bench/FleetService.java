package org.ripv.bench;

import java.util.ArrayList;
import java.util.List;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.VehicleEvent;
import org.ripv.service.RIPVService;
import org.ripv.service.Reply;

/**
 * A fleet for the fleet page's benchmark: one service with N vehicle MailBoxes, each of which has
 * surfaced once at a position of its own, so the page has a state, a fix and an event per vehicle.
 */
final class FleetService extends RIPVService {
    private final int vehicles;
    private final List<String> mailboxes = new ArrayList<>();

    FleetService(String host, int vehicles) {
        super("Fleet", "100201", host);
        this.vehicles = vehicles;
    }

    @Override
    protected void open() {
        for (int i = 1; i <= vehicles; i++) {
            mailboxes.add(openMailBox(String.format("g%03d", i), request -> Reply.error(ErrorCode.UNKNOWN_COMMAND,
                    "a benchmark vehicle answers nothing")).toString());
        }
    }

    @Override
    protected String description() {
        return "Benchmark vehicles that surfaced once each";
    }

    /** Each vehicle surfaces once, somewhere off Cape Cod. */
    void surfaceAll() {
        for (int i = 0; i < mailboxes.size(); i++) {
            publish(ConsoleEntry.event(mailboxes.get(i), VehicleEvent.SURFACED, "bench", 41.0 + i * 0.01, -70.0 - i * 0.01));
        }
    }
}
