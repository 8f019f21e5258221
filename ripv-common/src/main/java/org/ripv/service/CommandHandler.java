package org.ripv.service;

/**
 * Runs the commands of one MailBox (thesis: a Handler). {@link #execute} is called for one
 * request at a time, so a handler may keep a conversation with its device without locking.
 */
@FunctionalInterface
public interface CommandHandler {

    /**
     * Runs one command. Throw {@link org.ripv.exceptions.ServiceException} to answer with a
     * specific error; any other exception answers INTERNAL with its message.
     */
    Reply execute(Request request) throws Exception;

    /** Whether the resource can take commands now ({@code ?status}). Called from other threads. */
    default Availability availability() {
        return Availability.available("");
    }
}
