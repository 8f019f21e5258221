package org.ripv.client.managers;

import java.util.List;
import java.util.concurrent.Executor;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.Priority;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.SessionInfo;

/**
 * Keeps the service tabs, the SEL and MAM trees and each tab's target MailBox in step with what
 * the server lists, and picks the vehicle the window opens on. Model changes run on the UI
 * executor; the requests it sends go through {@link Requests}.
 */
final class MailboxTargets {
    private final ClientModel model;
    private final Executor ui;
    private final Requests requests;

    MailboxTargets(ClientModel model, Executor ui, Requests requests) {
        this.model = model;
        this.ui = ui;
        this.requests = requests;
    }

    /** The MailBox address belongs to the service named (its address starts with the service's). */
    static boolean belongsTo(String mailbox, String service) {
        return mailbox.startsWith(service) && mailbox.length() > service.length();
    }

    /** A MailBox the operator calls a vehicle: one with a call state (it has published call events). */
    static boolean isVehicle(MailboxStatus m) {
        return m.session() != null;
    }

    void services(List<ServiceDescriptor> services) {
        ui.execute(() -> {
            if (model.services(services)) {
                // A new service: its MailBoxes now, not at the next periodic refresh.
                requests.background("?mailboxes");
            }
        });
    }

    void mailboxes(List<MailboxStatus> mailboxes) {
        ui.execute(() -> {
            for (ServiceModel s : model.services()) {
                List<MailboxStatus> mine = mailboxes.stream().filter(m -> belongsTo(m.address(), s.name())).toList();
                boolean pickFirst = s.target().isEmpty() && !mine.isEmpty();
                if (!mine.equals(s.mailboxes())) {
                    s.mailboxes(mine);
                    model.fire(ClientModel.Kind.MAILBOXES, s.name());
                    model.fire(ClientModel.Kind.COM, s.name());
                }
                if (pickFirst) {
                    // One obvious target saves a click (a vehicle before a plain port); the MAM tree still shows the choice.
                    requests.selectMailbox(s.name(), firstVehicle(mine).address());
                }
            }
            openOnFirstVehicle();
        });
    }

    void status(MailboxStatus status) {
        ui.execute(() -> {
            for (ServiceModel s : model.services()) {
                if (belongsTo(status.address(), s.name())) {
                    s.status(status);
                    model.fire(ClientModel.Kind.MAILBOXES, s.name());
                    model.fire(ClientModel.Kind.COM, s.name());
                }
            }
        });
    }

    void session(SessionInfo session) {
        ui.execute(() -> {
            model.session(session);
            // A new connection (after a drop) watches nothing yet: watch the targets again.
            for (ServiceModel m : model.services()) {
                if (!m.target().isEmpty()) {
                    requests.send("", "?watch " + m.target(), Priority.NORMAL, null);
                }
            }
        });
    }

    private static MailboxStatus firstVehicle(List<MailboxStatus> mailboxes) {
        return mailboxes.stream().filter(MailboxTargets::isVehicle).findFirst().orElse(mailboxes.get(0));
    }

    /**
     * The window opens on the first vehicle: the first service with a vehicle MailBox, else the first
     * SerialPortServer, with that MailBox its target. Decided once, when the first MailBoxes come.
     */
    private void openOnFirstVehicle() {
        if (!model.opening().isEmpty()) {
            return;
        }
        ServiceModel chosen = null;
        for (ServiceModel s : model.services()) {
            if (s.mailboxes().stream().anyMatch(MailboxTargets::isVehicle)) {
                chosen = s;
                break;
            }
            if (chosen == null && s.descriptor() != null && Ids.SID_SERIAL.equals(s.descriptor().sid())
                    && !s.mailboxes().isEmpty()) {
                chosen = s;
            }
        }
        if (chosen != null && model.openOn(chosen.name())) {
            MailboxStatus first = firstVehicle(chosen.mailboxes());
            if (!first.address().equals(chosen.target())) {
                requests.selectMailbox(chosen.name(), first.address());
            }
            model.fire(ClientModel.Kind.SERVICES, null);
        }
    }
}
