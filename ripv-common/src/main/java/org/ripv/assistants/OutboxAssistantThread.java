package org.ripv.assistants;

import java.util.ArrayList;
import java.util.List;
import org.ripv.managers.TaskManager;
import org.ripv.messages.Message;
import org.ripv.post.MailBox;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Takes replies off a MailBox's outbox and hands them to the TaskManager's footer side — one at
 * a time when they come one at a time, together when several have queued up meanwhile.
 */
public final class OutboxAssistantThread<I extends Message, O extends Message> extends AssistantThread<I, O> {
    private static final Logger log = LoggerFactory.getLogger(OutboxAssistantThread.class);

    /** The most replies handed to the TaskManager at once. */
    static final int MAX_BATCH = 256;

    public OutboxAssistantThread(MailBox<I, O> box, TaskManager<I, O> manager) {
        super(box, manager, "outbox");
    }

    @Override
    public void run() {
        List<O> batch = new ArrayList<>();
        while (true) {
            O reply;
            try {
                // Once stopping, deliver what is left without waiting for more.
                reply = running ? box.takeReply() : box.pollReply();
            } catch (InterruptedException e) {
                reply = box.pollReply();
            }
            if (reply == null) {
                break;
            }
            batch.clear();
            batch.add(reply);
            box.drainReplies(batch, MAX_BATCH - 1);
            try {
                if (batch.size() == 1) {
                    manager.parseFooter(box, reply);
                } else {
                    manager.parseFooters(box, batch);
                }
            } catch (Throwable t) {
                log.warn("{}: could not deliver {} repl{}", box.address(), batch.size(), batch.size() == 1 ? "y" : "ies", t);
                for (O r : batch) {
                    manager.undeliverable(box, r, t);
                }
            }
        }
        log.debug("{} stopped", getName());
    }

}
