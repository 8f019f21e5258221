package org.ripv.server.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.rmi.Remote;
import java.rmi.server.UnicastRemoteObject;
import org.junit.jupiter.api.Test;
import org.ripv.security.ServiceProof;

/** The server's half of the handshake: one-time challenges, proofs bound to the name and the exported object. */
class ServiceChallengesTest {
    static final String SECRET = "s3cret-s3cret-s3cret";

    interface Ping extends Remote {
    }

    @Test
    void aProofIsGoodOnceForItsChallengeNameAndStubOnly() throws Exception {
        ServiceChallenges c = new ServiceChallenges(() -> SECRET);
        Ping a = new Ping() { };
        Ping b = new Ping() { };
        Remote stubA = UnicastRemoteObject.exportObject(a, 0);
        Remote stubB = UnicastRemoteObject.exportObject(b, 0);
        try {
            String ns = ServiceProof.nonce();
            String[] answer = c.challenge(ns).split(" ");
            assertThat(answer[1]).isEqualTo(ServiceProof.serverProof(SECRET, ns, answer[0]));
            String proof = answer[0] + " " + ns + " " + ServiceProof.serviceProof(SECRET, ns, answer[0], "<X>::<h>", stubA);

            // A relay that swaps in its own object, or another name, is refused (and uses up the challenge).
            assertThatThrownBy(() -> c.verify(proof, "<X>::<h>", stubB)).isInstanceOf(SecurityException.class);
            String ns2 = ServiceProof.nonce();
            String[] answer2 = c.challenge(ns2).split(" ");
            String proof2 = answer2[0] + " " + ns2 + " " + ServiceProof.serviceProof(SECRET, ns2, answer2[0], "<X>::<h>", stubA);
            assertThatThrownBy(() -> c.verify(proof2, "<Y>::<h>", stubA)).isInstanceOf(SecurityException.class);

            String ns3 = ServiceProof.nonce();
            String[] answer3 = c.challenge(ns3).split(" ");
            String proof3 = answer3[0] + " " + ns3 + " " + ServiceProof.serviceProof(SECRET, ns3, answer3[0], "<X>::<h>", stubA);
            ServiceChallenges.Accepted ok = c.verify(proof3, "<X>::<h>", stubA);
            assertThat(ok.token()).isEqualTo(ServiceProof.token(SECRET, ns3, answer3[0])).doesNotContain(SECRET);
            assertThatThrownBy(() -> c.verify(proof3, "<X>::<h>", stubA)).as("replayed").isInstanceOf(SecurityException.class)
                    .hasMessageContaining("unknown, used or expired");

            String wrong = ServiceProof.nonce();
            String[] answer4 = c.challenge(wrong).split(" ");
            String forged = answer4[0] + " " + wrong + " " + ServiceProof.serviceProof("guess", wrong, answer4[0], "<X>::<h>", stubA);
            assertThatThrownBy(() -> c.verify(forged, "<X>::<h>", stubA)).hasMessageContaining("wrong service secret");
            assertThatThrownBy(() -> c.challenge("not a nonce")).isInstanceOf(IllegalArgumentException.class);
        } finally {
            UnicastRemoteObject.unexportObject(a, true);
            UnicastRemoteObject.unexportObject(b, true);
        }
    }

    @Test
    void noFloodOfChallengesPushesOutAServicesChallenge() throws Exception {
        // Issue 23, item 1: the newest 256 were kept, so 256 more refused the service ("unknown").
        ServiceChallenges c = new ServiceChallenges(() -> SECRET);
        Ping a = new Ping() { };
        Remote stub = UnicastRemoteObject.exportObject(a, 0);
        try {
            String ns = ServiceProof.nonce();
            String[] answer = c.challenge(ns).split(" ");
            for (int i = 0; i < 100_000; i++) {
                c.challenge(ServiceProof.nonce());
            }
            String proof = answer[0] + " " + ns + " " + ServiceProof.serviceProof(SECRET, ns, answer[0], "<X>::<h>", stub);
            assertThat(c.verify(proof, "<X>::<h>", stub).token()).isEqualTo(ServiceProof.token(SECRET, ns, answer[0]));

            // A server nonce is good only with the service nonce it was issued for, and only from this server.
            String ns2 = ServiceProof.nonce();
            String[] answer2 = c.challenge(ns2).split(" ");
            String other = ServiceProof.nonce();
            String swapped = answer2[0] + " " + other + " " + ServiceProof.serviceProof(SECRET, other, answer2[0], "<X>::<h>", stub);
            assertThatThrownBy(() -> c.verify(swapped, "<X>::<h>", stub)).hasMessageContaining("register again");
            String invented = ServiceProof.nonce();
            String made = invented + " " + ns2 + " " + ServiceProof.serviceProof(SECRET, ns2, invented, "<X>::<h>", stub);
            assertThatThrownBy(() -> new ServiceChallenges(() -> SECRET).verify(made, "<X>::<h>", stub))
                    .hasMessageContaining("unknown, used or expired");
        } finally {
            UnicastRemoteObject.unexportObject(a, true);
        }
    }
}
