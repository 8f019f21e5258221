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
     * The first step of registering: the service sends a fresh nonce and the server proves that
     * it holds the service secret without revealing it ({@link org.ripv.security.ServiceProof}).
     * A service sends nothing derived from the secret to a server whose proof is wrong.
     *
     * @param serviceNonce 32 hex digits from {@link org.ripv.security.ServiceProof#nonce}
     * @return {@code "SERVERNONCE PROOF"}: the server's own nonce and
     *         {@link org.ripv.security.ServiceProof#serverProof}
     */
    String challenge(String serviceNonce) throws RemoteException;

    /**
     * Registers a service with the server, after {@link #challenge}.
     *
     * @param descriptor the service's name, SID and client-side hints
     * @param service    the service's own exported stub, which the server will call
     * @param proof      {@code "SERVERNONCE PROOF"}: the nonce the challenge returned and
     *                   {@link org.ripv.security.ServiceProof#serviceProof}; never the secret itself
     * @return {@link org.ripv.security.ServiceProof#serverProof} over the two nonces in reverse
     *         order, confirming the registration. Both sides use
     *         {@link org.ripv.security.ServiceProof#token} as the session token of all later calls.
     * @throws SecurityException when the proof is wrong, or the challenge unknown or used
     */
    String register(ServiceDescriptor descriptor, GenericRMIInterface service, String proof) throws RemoteException;

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
     * @return true when that request was running and its handler accepted the cancel, or when it
     *         has not started there (still on its way, or waiting): it is then answered CANCELLED
     *         and never runs; false when its handler cannot stop it
     * @throws UnsupportedOperationException from a side that runs no service MailBoxes (the default)
     */
    default boolean cancel(String token, String mailbox, String clientId, long messageId) throws RemoteException {
        throw new UnsupportedOperationException("this side runs no service MailBoxes; send ?cancel to the server");
    }

    /**
     * Tells a service that a page of the table a request is sending (a PROGRESS reply with a
     * {@code TableResult}, {@code org.ripv.messages.TablePages}) went out to the client's socket,
     * so the next may go: a result is never held on its way in more than a couple of pages.
     *
     * @return true when that request is still running there
     * @throws UnsupportedOperationException from a side that runs no service MailBoxes (the default)
     */
    default boolean more(String token, String mailbox, String clientId, long messageId) throws RemoteException {
        throw new UnsupportedOperationException("this side runs no service MailBoxes");
    }

    /**
     * Asked of the server by a registered service: the stub of another registered service, so that
     * it can read a file that one holds ({@link #handout}).
     *
     * @return null when that service is not registered, or cannot be reached but through the
     *         server (it registered outbound-only)
     * @throws UnsupportedOperationException from a service (the default)
     */
    default GenericRMIInterface peer(String token, String service) throws RemoteException {
        throw new UnsupportedOperationException("only the RIPVServer knows the other services");
    }

    /**
     * Asked of a service by another: the next chunk of a file this service fetched and still
     * holds, by a ticket the server signed ({@link org.ripv.handout.Handouts#read}). The ticket is
     * the caller's credential: it needs no session token.
     *
     * @throws SecurityException when the ticket is forged, used, expired, or its file let go
     * @throws UnsupportedOperationException from a side that holds no files (the default)
     */
    default byte[] handout(String ticket, long offset, int max) throws RemoteException {
        throw new UnsupportedOperationException("this side holds no files to hand out");
    }

    /** The service's MailBoxes and whether each can take commands now. */
    List<MailboxStatus> mailboxes(String token) throws RemoteException;
}
