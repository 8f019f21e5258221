package org.ripv.server.workflow;

import java.io.IOException;
import java.nio.file.Files;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * At the start of a call's run, the files waiting in the MailBox's {@code to-vehicle/} folder
 * (issue 24, item 3): each goes to the service as {@code tovehicle:put to-vehicle/FOLDER/NAME}
 * from the run's client id, as the user who uploaded it (so the permit file and the operator lock
 * apply as for that user's command), oldest first. The service sends it by the link's protocol
 * and checks the vehicle's {@code dir}; only then does it move to {@code sent/} with a receipt.
 * Anything else leaves it where it is for the next call.
 *
 * <p>It lives beside the runner because it is part of the call's run: the same request path, the
 * same lock, cut by the same end of the call.
 */
final class ToVehicleRun {
    private static final Logger log = LoggerFactory.getLogger(ToVehicleRun.class);
    /** The service's command; its first argument is the attached file's to-vehicle name. */
    static final String COMMAND = "tovehicle:put";

    private final Workflows workflows;
    private final String mailbox;
    private final StepRequests requests;

    ToVehicleRun(Workflows workflows, String mailbox, StepRequests requests) {
        this.workflows = workflows;
        this.mailbox = mailbox;
        this.requests = requests;
    }

    /** Sends what waits; stops at a cut call, a link that does not send them, or an operator's lock. */
    void run(String clientId) throws IOException {
        List<String> waiting = workflows.host.files().toVehiclePending(mailbox);
        int sent = 0;
        for (String name : waiting) {
            String owner = workflows.host.files().owner(name);
            if (owner.isEmpty()) {
                workflows.announce(mailbox, Workflows.SERVER, "to-vehicle: " + name + " stays: nobody uploaded it through RIPV (put there"
                        + " by hand?), so no one's rights can send it; upload it with put");
                continue;
            }
            long size = Files.size(workflows.host.files().uploadPath(name));
            // generous: a 2,400-baud line moves about 240 bytes a second, and a call starts slowly
            Duration timeout = Duration.ofSeconds(120 + size / 100);
            QueuedWorkflow as = new QueuedWorkflow(0, owner, name, 0, "", QueuedWorkflow.State.RUNNING, 0, 1, "", List.of(),
                    null);
            long t0 = System.currentTimeMillis();
            OutgoingServerMessage r;
            try {
                r = requests.send(as, clientId, mailbox, COMMAND + " " + name, timeout);
            } catch (StepStop.Cut | StepStop.Preempted stop) {
                workflows.announce(mailbox, owner, "to-vehicle: " + name + " stays for the next call: " + stop.getMessage());
                return;
            } catch (StepStop.Failed f) {
                workflows.announce(mailbox, owner, "to-vehicle: " + name + " stays for the next call: " + f.getMessage());
                continue;
            } catch (StepStop other) {
                return; // the sealed type has no other kinds
            }
            String text = r.footer().replyText();
            if (r.status() != Status.OK) {
                workflows.announce(mailbox, owner, "to-vehicle: " + name + " stays for the next call: " + r.footer().errorCode()
                        + ": " + text);
                if (r.footer().errorCode() == ErrorCode.NOT_AVAILABLE || r.footer().errorCode() == ErrorCode.MAILBOX_LOCKED) {
                    return; // the link does not send them, or someone holds it: the rest would fail the same way
                }
                continue;
            }
            String receipt = "file: " + name + "\nbytes: " + size + "\nmailbox: " + mailbox + "\nuploaded by: " + owner
                    + "\nsent: " + Instant.ofEpochMilli(t0) + " to " + Instant.now() + "\nservice: " + text + "\n";
            String where = workflows.host.files().toVehicleSent(name, receipt);
            sent++;
            workflows.announce(mailbox, owner, "to-vehicle: " + text + "; moved to " + where + " (receipt " + where
                    + ".receipt)");
        }
        if (!waiting.isEmpty()) {
            log.info("{}: to-vehicle: {} of {} waiting file(s) sent on this call", mailbox, sent, waiting.size());
        }
    }
}
