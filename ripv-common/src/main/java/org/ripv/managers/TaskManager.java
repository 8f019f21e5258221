package org.ripv.managers;

import java.util.List;
import org.ripv.messages.Message;
import org.ripv.post.MailBox;

/**
 * Decides what a message means (thesis 5.2.6). The inbox assistant hands it each request
 * ({@link #parseHeader}) one at a time per MailBox; the outbox assistant hands it each reply
 * ({@link #parseFooter}). On the server the header side forwards to a service or runs a
 * {@code ?} command, and the footer side writes to the client's socket; on a service the header
 * side runs the command against the resource and the footer side calls {@code serviceReply}.
 */
public abstract class TaskManager<I extends Message, O extends Message> {

    /**
     * Runs the command of a request. Returns when the command has finished; replies go to
     * {@code box.post(...)}. While it runs, the MailBox's key is held.
     */
    public abstract void parseHeader(MailBox<I, O> box, I request) throws Exception;

    /** Delivers a reply taken from the outbox. */
    public abstract void parseFooter(MailBox<I, O> box, O reply) throws Exception;

    /**
     * Delivers several replies that were waiting in the outbox together, in order. The default
     * delivers them one by one; a TaskManager whose delivery has a per-call cost (an RMI call)
     * sends them at once.
     */
    public void parseFooters(MailBox<I, O> box, List<O> replies) {
        for (O reply : replies) {
            try {
                parseFooter(box, reply);
            } catch (Exception e) {
                undeliverable(box, reply, e);
            }
        }
    }

    /**
     * Called when {@link #parseHeader} throws: the request must still get its one final reply.
     */
    public abstract void failed(MailBox<I, O> box, I request, Throwable cause);

    /** Called when {@link #parseFooter} throws. The default only lets the assistant log it. */
    public void undeliverable(MailBox<I, O> box, O reply, Throwable cause) {
    }
}
