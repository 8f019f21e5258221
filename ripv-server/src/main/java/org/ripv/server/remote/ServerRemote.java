package org.ripv.server.remote;

import java.util.List;
import java.util.function.BiConsumer;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.server.handout.HandoutTickets;
import org.ripv.server.requests.ServiceReplies;
import org.ripv.server.security.ServiceChallenges;
import org.ripv.server.services.ServiceAdmission;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceRegistry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server's side of {@link GenericRMIInterface}: registration by challenge–response over the
 * service secret ({@link ServiceChallenges}),
 * replies called back by services, and their heartbeats. Every call but {@code register}
 * must carry the token the registration handed out.
 */
public final class ServerRemote implements GenericRMIInterface {
    private static final Logger log = LoggerFactory.getLogger(ServerRemote.class);

    private final ServiceChallenges challenges;
    private final ServiceAdmission admission;
    private final ServiceRegistry services;
    private final ServiceReplies replies;
    private final BiConsumer<ServiceReference, List<ConsoleEntry>> console;
    private final HandoutTickets handouts;

    /**
     * @param console takes the console entries a service published for its MailBoxes
     */
    public ServerRemote(ServiceChallenges challenges, ServiceAdmission admission, ServiceRegistry services,
                        ServiceReplies replies, BiConsumer<ServiceReference, List<ConsoleEntry>> console) {
        this.challenges = challenges;
        this.admission = admission;
        this.services = services;
        this.replies = replies;
        this.console = console;
        this.handouts = new HandoutTickets(services);
    }

    @Override
    public String challenge(String serviceNonce) {
        return challenges.challenge(serviceNonce);
    }

    @Override
    public String register(ServiceDescriptor d, GenericRMIInterface service, String proof) {
        ServiceChallenges.Accepted accepted = challenges.verify(proof, d == null ? null : d.name(), service);
        admission.admit(d, service, accepted.token());
        return accepted.confirmation();
    }

    @Override
    public void serviceReply(String token, OutgoingServiceMessage reply) {
        replies.accept(byToken(token), reply);
    }

    @Override
    public void serviceReplies(String token, List<OutgoingServiceMessage> replies) {
        ServiceReference ref = byToken(token);
        ServiceReplies accepting = this.replies;
        for (OutgoingServiceMessage reply : replies) {
            accepting.accept(ref, reply);
        }
    }

    @Override
    public void console(String token, List<ConsoleEntry> entries) {
        console.accept(byToken(token), entries);
    }

    @Override
    public void serviceRequests(String token, List<IncomingServiceMessage> requests) {
        throw new UnsupportedOperationException("the RIPVServer takes no service requests");
    }

    @Override
    public boolean heartbeat(String token) {
        return services.byToken(token).isPresent();
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

    /** A service that holds a ticket asks where the file's holder is (org.ripv.handout). */
    @Override
    public GenericRMIInterface peer(String token, String service) {
        return handouts.peer(token, service);
    }

    @Override
    public List<MailboxStatus> mailboxes(String token) {
        throw new UnsupportedOperationException("ask ?mailboxes over the client socket");
    }

    private ServiceReference byToken(String token) {
        return services.byToken(token).orElseThrow(() -> new SecurityException("unknown session token: register first"));
    }
}
