package org.ripv.server.security;

import java.rmi.Remote;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.Supplier;
import org.ripv.security.ServiceProof;

/**
 * The server's half of the registration handshake ({@link ServiceProof}): answers challenges with
 * proof of the secret, and accepts a registration only with a proof over a challenge it issued in
 * the last minute, once. Outstanding challenges are bounded, so nobody can fill memory with them.
 */
public final class ServiceChallenges {
    static final long LIFETIME_MILLIS = 60_000;
    static final int MAX_OUTSTANDING = 256;

    /** A registration that proved the secret: the session token, and the confirmation to return. */
    public record Accepted(String token, String confirmation) {}

    private record Issued(String serviceNonce, long expires) {}

    private final Supplier<String> secret;
    private final Map<String, Issued> issued = new LinkedHashMap<>(16, 0.75f, false) {
        private static final long serialVersionUID = 1L;

        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Issued> eldest) {
            return size() > MAX_OUTSTANDING;
        }
    };

    public ServiceChallenges(Supplier<String> secret) {
        this.secret = secret;
    }

    /** Answers {@code GenericRMIInterface.challenge}: {@code "SERVERNONCE PROOF"}. */
    public synchronized String challenge(String serviceNonce) {
        if (!ServiceProof.isNonce(serviceNonce)) {
            throw new IllegalArgumentException("a challenge is a nonce of 32 hex digits");
        }
        String mine = ServiceProof.nonce();
        issued.put(mine, new Issued(serviceNonce, System.currentTimeMillis() + LIFETIME_MILLIS));
        return mine + " " + ServiceProof.serverProof(secret.get(), serviceNonce, mine);
    }

    /**
     * Checks a registration's proof.
     *
     * @throws SecurityException when it does not prove the secret for this challenge, name and stub
     */
    public Accepted verify(String proof, String serviceName, Remote stub) {
        String[] w = proof == null ? new String[0] : proof.split(" ");
        if (w.length != 2 || !ServiceProof.isNonce(w[0])) {
            Audit.log(true, "register-refused", "service", serviceName, "reason", "no-challenge-proof");
            throw new SecurityException("no proof of the service secret: this service is older than the server"
                    + " or does not hold DATA/service.secret (give it with --secret-file)");
        }
        Issued i;
        synchronized (this) {
            i = issued.remove(w[0]);
        }
        if (i == null || i.expires() < System.currentTimeMillis()) {
            Audit.log(true, "register-refused", "service", serviceName, "reason", "unknown-or-used-challenge");
            throw new SecurityException("the registration's challenge is unknown, used or expired; register again");
        }
        String s = secret.get();
        if (serviceName == null || stub == null || !ServiceProof.same(w[1], ServiceProof.serviceProof(s, i.serviceNonce(), w[0], serviceName, stub))) {
            Audit.log(true, "register-refused", "service", serviceName, "reason", "wrong-secret");
            throw new SecurityException("wrong service secret: give the server's DATA/service.secret with --secret-file");
        }
        Audit.log(false, "register", "service", serviceName);
        return new Accepted(ServiceProof.token(s, i.serviceNonce(), w[0]), ServiceProof.serverProof(s, w[0], i.serviceNonce()));
    }
}
