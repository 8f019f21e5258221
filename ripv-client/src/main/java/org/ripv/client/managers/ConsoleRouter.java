package org.ripv.client.managers;

import java.awt.image.BufferedImage;
import java.util.Objects;
import java.util.concurrent.Executor;
import org.ripv.client.managers.ServiceModel.LineKind;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.ImageResult;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.messages.VehicleEvent;

/**
 * Routes what the server says about a service's work to the parts of the model that show it:
 * replies and progress to the tab's COM panel, tables to DAB, pictures to DAV, console lines to
 * the console and the badges, workflow outcomes to the status bar and alerts to the desktop. It
 * also asks the server to cancel a running request and to send older console lines. Model
 * changes run on the UI executor.
 */
record ConsoleRouter(ClientModel model, Executor ui, Requests requests, DesktopNotice desktop) {
    void reply(String service, LineKind kind, String text) {
        ui.execute(() -> {
            ServiceModel m = service == null ? null : model.service(service);
            if (m == null) {
                // The service vanished meanwhile (or never registered): say it in the status bar.
                model.notice((service == null ? "" : service + ": ") + text, kind == LineKind.ERROR);
                return;
            }
            m.append(kind, text);
            model.fire(ClientModel.Kind.COM, service);
            if (kind == LineKind.ERROR || kind == LineKind.REPLY || kind == LineKind.NOTICE) {
                // The status bar shows the latest outcome: a later success replaces an error.
                model.notice(service + ": " + text, kind == LineKind.ERROR);
            }
        });
    }

    void progress(String service, Progress progress) {
        if (service == null) {
            return;
        }
        ui.execute(() -> {
            ServiceModel m = model.service(service);
            if (m != null && !Objects.equals(m.progress(), progress)) {
                m.progress(progress);
                model.fire(ClientModel.Kind.COM, service);
            }
        });
    }

    void started(String service, long messageId, String command) {
        ui.execute(() -> {
            ServiceModel m = model.service(service);
            if (m != null) {
                m.started(messageId, command, System.currentTimeMillis());
                model.fire(ClientModel.Kind.COM, service);
            }
        });
    }

    void progress(String service, long messageId, Progress progress) {
        ui.execute(() -> {
            ServiceModel m = service == null ? null : model.service(service);
            if (m != null && m.progress(messageId, progress)) {
                model.fire(ClientModel.Kind.COM, service);
            }
        });
    }

    void ended(String service, long messageId, ErrorCode code) {
        ui.execute(() -> {
            ServiceModel m = model.service(service);
            if (m != null && m.ended(messageId) != null) {
                model.fire(ClientModel.Kind.COM, service);
            }
        });
    }

    /** See {@link GuiManager#cancel}. Call on the UI thread. */
    void cancel(String service, long messageId) {
        ServiceModel m = model.service(service);
        if (m == null || !m.cancelling(messageId, true)) {
            return;
        }
        model.fire(ClientModel.Kind.COM, service);
        requests.call("?cancel " + messageId, (reply, e) -> {
            boolean refused = e != null || reply.status() == Status.ERROR;
            if (e != null) {
                notice("'?cancel " + messageId + "' got no reply: " + Failures.describe(e), true);
            }
            if (refused) {
                ui.execute(() -> {
                    ServiceModel now = model.service(service);
                    if (now != null && now.cancelling(messageId, false)) {
                        model.fire(ClientModel.Kind.COM, service);
                    }
                });
            } else if (!reply.footer().replyText().isBlank()) {
                notice(reply.footer().replyText(), false);
            }
        });
    }

    void table(String service, TableResult table) {
        ui.execute(() -> {
            ServiceModel m = service == null ? null : model.service(service);
            if (m != null) {
                m.addTable(table);
                model.fire(ClientModel.Kind.TABLES, service);
            }
        });
    }

    void image(String service, ImageResult image, BufferedImage decoded) {
        ui.execute(() -> {
            ServiceModel m = service == null ? null : model.service(service);
            if (m != null) {
                m.picture(new ServiceModel.Picture(image, decoded));
                model.fire(ClientModel.Kind.IMAGE, service);
            }
        });
    }

    /** Asks the server's transcript for older lines of a MailBox's console. Any thread. */
    void loadHistory(String mailbox) {
        if (mailbox != null && !mailbox.isEmpty()) {
            requests.send("", "?history " + mailbox + " --last " + ConsoleModel.MAX_ENTRIES / 5, Priority.NORMAL, null);
        }
    }

    void history(ConsoleBatch batch) {
        ui.execute(() -> model.console().addHistory(batch));
    }

    void console(ConsoleBatch batch, boolean live) {
        ui.execute(() -> {
            model.console().add(batch);
            for (ServiceModel s : model.services()) {
                if (MailboxTargets.belongsTo(batch.mailbox(), s.name()) && s.console(batch.mailbox(), batch.entries())) {
                    model.fire(ClientModel.Kind.MAILBOXES, s.name()); // the badges in SEL and MAM
                    model.fire(ClientModel.Kind.COM, s.name()); // and SS, from the same state
                }
            }
            if (live) {
                batch.entries().forEach(this::announce);
            }
        });
    }

    void notice(String text, boolean error) {
        ui.execute(() -> model.notice(text, error));
    }

    /** A live workflow outcome goes to the status bar; an event worth a pilot's attention to the desktop. */
    private void announce(ConsoleEntry e) {
        String vehicle = e.mailbox().substring(e.mailbox().lastIndexOf('>') + 1);
        if (e.kind() == ConsoleEntry.Kind.EVENT && e.event().endsWorkflow()) {
            model.notice(vehicle + " " + e.event() + (e.text().isEmpty() ? "" : ": " + e.text()),
                    e.event() != VehicleEvent.WORKFLOW_DONE);
        }
        if (ConsoleModel.notifies(e)) {
            desktop.show("RIPV: " + vehicle + " " + e.event(), e.text().isEmpty() ? e.mailbox() : e.text(),
                    e.event() == VehicleEvent.ALERT);
        }
    }
}
