package org.ripv.assistants;

import org.ripv.managers.TaskManager;
import org.ripv.messages.Message;
import org.ripv.post.MailBox;

/**
 * What the inbox and outbox assistants share: the MailBox they serve and its TaskManager, a name
 * ({@code mailbox-ADDRESS-inbox} or {@code -outbox}), a running flag, and how they stop.
 */
abstract class AssistantThread<I extends Message, O extends Message> extends Thread {
    protected final MailBox<I, O> box;
    protected final TaskManager<I, O> manager;
    protected volatile boolean running = true;

    AssistantThread(MailBox<I, O> box, TaskManager<I, O> manager, String side) {
        super("mailbox-" + box.address() + "-" + side);
        this.box = box;
        this.manager = manager;
        setDaemon(true);
    }

    /**
     * Stops: interrupts what the assistant is waiting on or running (a handler blocked on a
     * device sees the interrupt and fails, which still answers its request) and waits up to the
     * given milliseconds for it to finish.
     */
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
