package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.rmi.RmiSupport;

/**
 * A registration that arrives after a newer one of the same service — an attempt the service
 * gave up on, completing late — is refused and never replaces the registration in force; a
 * newer one does. Over real RMI, with real exported service objects.
 */
class LateRegistrationTest {
    @TempDir
    Path dir;

    @Test
    void anOlderAttemptNeverReplacesANewerRegistration() throws Exception {
        try (TestSystem sys = TestSystem.start(dir)) {
            GenericRMIInterface server = (GenericRMIInterface) RmiSupport.registry("localhost", sys.server().registryPort())
                    .lookup(GenericRMIInterface.BINDING);
            ServiceDescriptor d = new ServiceDescriptor("<ClockService>::<late>", "100100", "late", "", List.of());
            Probe newer = new Probe();
            Probe older = new Probe();
            Probe newest = new Probe();
            try {
                String token = register(server, d.withRegistration(2_000), RmiSupport.export(newer, 0), sys.secret());
                assertThatThrownBy(() -> register(server, d.withRegistration(1_000), RmiSupport.export(older, 0), sys.secret()))
                        .isInstanceOf(IllegalStateException.class).hasMessageContaining("superseded");
                assertThat(server.heartbeat(token)).as("the newer registration is still in force").isTrue();
                assertThat(sys.server().serviceCount()).isEqualTo(1);

                String latest = register(server, d.withRegistration(3_000), RmiSupport.export(newest, 0), sys.secret());
                assertThat(server.heartbeat(latest)).isTrue();
                assertThat(server.heartbeat(token)).as("replaced by a newer attempt").isFalse();
            } finally {
                RmiSupport.unexport(newer);
                RmiSupport.unexport(older);
                RmiSupport.unexport(newest);
            }
        }
    }

    /** Registers as ServiceConnector does (challenge–response); returns the session token both sides derive. */
    static String register(GenericRMIInterface server, ServiceDescriptor d, GenericRMIInterface stub, String secret)
            throws java.rmi.RemoteException {
        String mine = org.ripv.security.ServiceProof.nonce();
        String[] answer = server.challenge(mine).split(" ");
        server.register(d, stub, answer[0] + " " + mine + " " + org.ripv.security.ServiceProof.serviceProof(secret, mine, answer[0], d.name(), stub));
        return org.ripv.security.ServiceProof.token(secret, mine, answer[0]);
    }

    /** A service object that answers the server's call-back and has no MailBoxes. */
    static final class Probe implements GenericRMIInterface {
        @Override public String challenge(String n) { throw new UnsupportedOperationException(); }
        @Override public String register(ServiceDescriptor d, GenericRMIInterface s, String secret) { throw new UnsupportedOperationException(); }
        @Override public void serviceReply(String t, OutgoingServiceMessage r) { throw new UnsupportedOperationException(); }
        @Override public void serviceReplies(String t, List<OutgoingServiceMessage> r) { throw new UnsupportedOperationException(); }
        @Override public void console(String t, List<ConsoleEntry> e) { throw new UnsupportedOperationException(); }
        @Override public boolean heartbeat(String t) { return true; }
        @Override public void serviceRequest(String t, IncomingServiceMessage r) { }
        @Override public void serviceRequests(String t, List<IncomingServiceMessage> r) { }
        @Override public boolean withdraw(String t, String m, String c, long id) { return false; }
        @Override public List<MailboxStatus> mailboxes(String t) { return List.of(); }
    }
}
