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

    /**
     * Stops the command {@link #execute} is running now, from another thread ({@code ?cancel}):
     * e.g. {@code Statement.cancel} for a query, an abort for a transfer. {@code execute} should
     * then return soon, with an error; the reply goes out as ERROR CANCELLED. The default cannot
     * stop anything.
     *
     * @param running the request being cancelled
     * @return true when the handler will stop it
     */
    default boolean cancel(Request running) {
        return false;
    }

    /** Whether the resource can take commands now ({@code ?status}). Called from other threads. */
    default Availability availability() {
        return Availability.available("");
    }
}
