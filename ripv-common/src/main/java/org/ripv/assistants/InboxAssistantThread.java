package org.ripv.assistants;

import org.ripv.managers.TaskManager;
import org.ripv.messages.Header;
import org.ripv.messages.Message;
import org.ripv.post.MailBox;
import org.ripv.post.MailBoxes;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Serves a MailBox's inboxes, serially and pre-emptively (thesis 5.2.6): it takes the oldest
 * message of the highest non-empty priority, holds the MailBox's key while the TaskManager runs
 * it, and takes the next only when that command has finished.
 */
public final class InboxAssistantThread<I extends Message, O extends Message> extends AssistantThread<I, O> {
    private static final Logger log = LoggerFactory.getLogger(InboxAssistantThread.class);

    public InboxAssistantThread(MailBox<I, O> box, TaskManager<I, O> manager) {
        super(box, manager, "inbox");
    }

    @Override
    public void run() {
        while (running) {
            I request;
            try {
                request = box.takeNext();
            } catch (InterruptedException e) {
                break;
            }
            MailBoxes.takeKey(box, request);
            try {
                manager.parseHeader(box, request);
            } catch (Throwable t) {
                if (t instanceof InterruptedException && !running) {
                    manager.failed(box, request, t);
                    break;
                }
                log.warn("{}: command '{}' failed", box.address(), Header.abbreviate(request.header().body()), t);
                manager.failed(box, request, t);
            } finally {
                MailBoxes.giveBackKey(box);
            }
        }
        log.debug("{} stopped", getName());
    }

}
