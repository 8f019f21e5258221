package org.ripv.server;

import java.util.List;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.server.security.ServiceChallenges;
import org.ripv.server.services.ServiceReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server's side of {@link GenericRMIInterface}: registration by challenge–response over the
 * service secret ({@link ServiceChallenges}),
 * replies called back by services, and their heartbeats. Every call but {@code register}
 * must carry the token the registration handed out.
 */
final class ServerRemote implements GenericRMIInterface {
    private static final Logger log = LoggerFactory.getLogger(ServerRemote.class);

    private final RIPVServer server;

    ServerRemote(RIPVServer server) {
        this.server = server;
    }

    @Override
    public String challenge(String serviceNonce) {
        return server.security().challenges().challenge(serviceNonce);
    }

    @Override
    public String register(ServiceDescriptor d, GenericRMIInterface service, String proof) {
        ServiceChallenges.Accepted accepted = server.security().challenges().verify(proof, d == null ? null : d.name(), service);
        ServiceAdmission.admit(server, d, service, accepted.token());
        return accepted.confirmation();
    }

    @Override
    public void serviceReply(String token, OutgoingServiceMessage reply) {
        ServiceReference ref = server.serviceMap().values().stream().filter(r -> r.token().equals(token)).findFirst()
                .orElseThrow(() -> new SecurityException("unknown session token: register first"));
        ServiceReplies.accept(server, ref, reply, server.pending());
    }

    @Override
    public void serviceReplies(String token, List<OutgoingServiceMessage> replies) {
        ServiceReference ref = server.serviceMap().values().stream().filter(r -> r.token().equals(token)).findFirst()
                .orElseThrow(() -> new SecurityException("unknown session token: register first"));
        for (OutgoingServiceMessage reply : replies) {
            ServiceReplies.accept(server, ref, reply, server.pending());
        }
    }

    @Override
    public void console(String token, List<ConsoleEntry> entries) {
        server.console(byToken(token), entries);
    }

    @Override
    public void serviceRequests(String token, List<IncomingServiceMessage> requests) {
        throw new UnsupportedOperationException("the RIPVServer takes no service requests");
    }

    @Override
    public boolean heartbeat(String token) {
        return server.serviceMap().values().stream().anyMatch(r -> r.token().equals(token));
    }

    @Override
    public void serviceRequest(String token, IncomingServiceMessage request) {
        throw new UnsupportedOperationException("the RIPVServer takes no service requests");
    }

    @Override
    public boolean withdraw(String token, String mailbox, String clientId, long messageId) {
        throw new UnsupportedOperationException("the RIPVServer runs no service MailBoxes");
    }

    @Override
    public boolean cancel(String token, String mailbox, String clientId, long messageId) {
        throw new UnsupportedOperationException("the RIPVServer runs no service MailBoxes; send ?cancel over the client socket");
    }

    @Override
    public List<MailboxStatus> mailboxes(String token) {
        throw new UnsupportedOperationException("ask ?mailboxes over the client socket");
    }

    private ServiceReference byToken(String token) {
        return server.serviceMap().values().stream().filter(r -> r.token().equals(token)).findFirst()
                .orElseThrow(() -> new SecurityException("unknown session token: register first"));
    }
}
