package org.ripv.rmi;

import java.rmi.Remote;
import java.rmi.RemoteException;
import java.util.List;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;

/**
 * The remote interface between the RIPVServer and its services (thesis 5.2.5). Both sides
 * export an object implementing it: the server answers {@link #register}, {@link #serviceReply}
 * and {@link #heartbeat}; a service answers {@link #serviceRequest} and {@link #mailboxes}. A
 * side asked for what it does not answer throws {@link UnsupportedOperationException}.
 *
 * <p>Calls after registration carry the token the server handed out, so that nobody who can
 * merely reach a port can inject requests or forge replies.
 */
public interface GenericRMIInterface extends Remote {

    /** The name the server binds in its RMI registry. */
    String BINDING = "RIPVServer";

    /**
     * Registers a service with the server.
     *
     * @param descriptor the service's name, SID and client-side hints
     * @param service    the service's own exported stub, which the server will call
     * @param secret     the server's service secret ({@code DATA/service.secret})
     * @return the session token for all later calls in both directions
     * @throws SecurityException when the secret is wrong
     */
    String register(ServiceDescriptor descriptor, GenericRMIInterface service, String secret) throws RemoteException;

    /** A service's reply (PROGRESS, OK or ERROR) to a request; called back on the server. */
    void serviceReply(String token, OutgoingServiceMessage reply) throws RemoteException;

    /**
     * Several replies in one call, in order: what a service sends when replies queue up under
     * load, so that one RMI round trip carries many.
     */
    void serviceReplies(String token, List<OutgoingServiceMessage> replies) throws RemoteException;

    /**
     * What a service's vehicles said and did on their own, in order: console lines, commands,
     * events and transfer lines (the live console). The server fans them out to watchers and keeps
     * the transcript; it never blocks the service on a slow watcher.
     */
    void console(String token, List<ConsoleEntry> entries) throws RemoteException;

    /**
     * A service's periodic sign of life. Asked of a service, it is the server's call-back probe at
     * registration (a service answers {@code true} whatever the token): proof that the server can
     * reach the service before it lists it.
     *
     * @return false when the server no longer knows the token (it restarted, or dropped the
     *         service): the service then registers again
     */
    boolean heartbeat(String token) throws RemoteException;

    /** A request for one of the service's MailBoxes; returns once the request is queued. */
    void serviceRequest(String token, IncomingServiceMessage request) throws RemoteException;

    /** Several requests in one call, in order (the server batches what queued up for a service). */
    void serviceRequests(String token, List<IncomingServiceMessage> requests) throws RemoteException;

    /**
     * Takes back a request that is still waiting in a MailBox's inbox (it timed out at the
     * server). A request already running cannot be withdrawn.
     *
     * @return true when the request was waiting and now will never run
     */
    boolean withdraw(String token, String mailbox, String clientId, long messageId) throws RemoteException;

    /**
     * Asks a service to stop a request that is running now ({@code ?cancel}). The MailBox's
     * handler decides how (a query's {@code Statement.cancel}, a transfer's abort); the request
     * still ends with exactly one final reply, an ERROR {@code CANCELLED} when the cancel took
     * effect. Withdraw a request that has not started with {@link #withdraw} instead.
     *
     * @param mailbox   the MailBox running it
     * @param clientId  the client id of the request's origin
     * @param messageId the request's message id
     * @return true when that request was running and its handler accepted the cancel; false when
     *         it is not running there or its handler cannot stop it
     * @throws UnsupportedOperationException from a side that runs no service MailBoxes (the default)
     */
    default boolean cancel(String token, String mailbox, String clientId, long messageId) throws RemoteException {
        throw new UnsupportedOperationException("this side runs no service MailBoxes; send ?cancel to the server");
    }

    /** The service's MailBoxes and whether each can take commands now. */
    List<MailboxStatus> mailboxes(String token) throws RemoteException;
}
