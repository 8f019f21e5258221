package org.ripv.assistants;

import org.ripv.managers.TaskManager;
import org.ripv.messages.Message;
import org.ripv.post.MailBox;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Takes replies off a MailBox's outbox and hands them to the TaskManager's footer side. */
public final class OutboxAssistantThread<I extends Message, O extends Message> extends Thread {
    private static final Logger log = LoggerFactory.getLogger(OutboxAssistantThread.class);

    private final MailBox<I, O> box;
    private final TaskManager<I, O> manager;
    private volatile boolean running = true;

    public OutboxAssistantThread(MailBox<I, O> box, TaskManager<I, O> manager) {
        super("mailbox-" + box.address() + "-outbox");
        this.box = box;
        this.manager = manager;
        setDaemon(true);
    }

    @Override
    public void run() {
        while (running) {
            O reply;
            try {
                reply = box.takeReply();
            } catch (InterruptedException e) {
                break;
            }
            try {
                manager.parseFooter(box, reply);
            } catch (Throwable t) {
                log.warn("{}: could not deliver reply {}", box.address(), reply, t);
                manager.undeliverable(box, reply, t);
            }
        }
        log.debug("{} stopped", getName());
    }

    public void shutdown(long waitMillis) {
        running = false;
        interrupt();
        try {
            join(waitMillis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
