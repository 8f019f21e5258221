package org.ripv.service;

import java.rmi.RemoteException;
import java.util.List;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.rmi.GenericRMIInterface;

/**
 * The service's side of {@link GenericRMIInterface}: what the server may call, each call checked
 * against the session's token; what only a server answers is refused.
 */
record ServiceRemote(RIPVService service, ServiceSession session) implements GenericRMIInterface {
    @Override
    public void serviceRequest(String t, IncomingServiceMessage request) throws RemoteException {
        session.check(t);
        service.accept(request);
    }

    @Override
    public void serviceRequests(String t, List<IncomingServiceMessage> requests) throws RemoteException {
        session.check(t);
        requests.forEach(service::accept);
    }

    @Override
    public boolean withdraw(String t, String mailbox, String clientId, long messageId) throws RemoteException {
        session.check(t);
        return service.withdraw(mailbox, clientId, messageId);
    }

    @Override
    public boolean cancel(String t, String mailbox, String clientId, long messageId) throws RemoteException {
        session.check(t);
        return service.cancel(mailbox, clientId, messageId);
    }

    @Override
    public boolean more(String t, String mailbox, String clientId, long messageId) throws RemoteException {
        session.check(t);
        return service.pageTaken(mailbox, clientId, messageId);
    }

    @Override
    public List<MailboxStatus> mailboxes(String t) throws RemoteException {
        session.check(t);
        return service.mailboxes();
    }

    /** Another service reads a file this one holds: the ticket is its credential, checked against this session. */
    @Override
    public byte[] handout(String ticket, long offset, int max) {
        return service.handout(ticket, offset, max, session.token());
    }

    @Override
    public String challenge(String nonce) {
        throw new UnsupportedOperationException("a service does not take registrations");
    }

    @Override
    public String register(ServiceDescriptor d, GenericRMIInterface s, String proof) {
        throw new UnsupportedOperationException("a service does not take registrations");
    }

    @Override
    public void serviceReply(String t, OutgoingServiceMessage reply) {
        throw new UnsupportedOperationException("a service does not take replies");
    }

    @Override
    public void serviceReplies(String t, List<OutgoingServiceMessage> replies) {
        throw new UnsupportedOperationException("a service does not take replies");
    }

    /** The server's call-back probe at registration: answering at all proves the server reaches us. */
    @Override
    public boolean heartbeat(String t) {
        return true;
    }

    @Override
    public void console(String t, List<ConsoleEntry> entries) {
        throw new UnsupportedOperationException("a service does not take console entries");
    }
}
