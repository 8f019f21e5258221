package org.ripv.server.security;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.rmi.Remote;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.Map;
import java.util.function.Supplier;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;
import org.ripv.security.ServiceProof;

/**
 * The server's half of the registration handshake ({@link ServiceProof}): answers challenges with
 * proof of the secret, and accepts a registration only with a proof over a challenge it issued in
 * the last minute, once.
 *
 * <p>A challenge keeps nothing on the server (issue 23, item 1): the server's nonce carries its
 * own expiry and a MAC, under a key of this process, over the service's nonce. Before, the newest
 * 256 challenges were kept, so anyone who could reach the registry pushed a service's challenge
 * out by asking for 256 more, and the service was refused. Now no number of challenges, from any
 * number of callers, takes a place from anyone: the only table is of challenges already used by a
 * registration that proved the secret, which only holders of the secret can fill. A challenge
 * costs the server one random number and two HMACs, and no memory.
 */
public final class ServiceChallenges {
    static final long LIFETIME_MILLIS = 60_000;
    /** Registrations that proved the secret within one lifetime; more means a loop in a service. */
    static final int MAX_USED = 4_096;
    private static final SecureRandom RANDOM = new SecureRandom();

    /** A registration that proved the secret: the session token, and the confirmation to return. */
    public record Accepted(String token, String confirmation) {}

    private final Supplier<String> secret;
    private final byte[] key = new byte[32];
    /** Server nonces a registration used, until they expire: each is accepted once. */
    private final Map<String, Long> used = new HashMap<>();

    public ServiceChallenges(Supplier<String> secret) {
        this.secret = secret;
        RANDOM.nextBytes(key);
    }

    /** Answers {@code GenericRMIInterface.challenge}: {@code "SERVERNONCE PROOF"}. */
    public String challenge(String serviceNonce) {
        if (!ServiceProof.isNonce(serviceNonce)) {
            throw new IllegalArgumentException("a challenge is a nonce of 32 hex digits");
        }
        ByteBuffer b = ByteBuffer.allocate(16);
        b.putInt((int) ((System.currentTimeMillis() + LIFETIME_MILLIS) / 1000));
        b.putInt(RANDOM.nextInt());
        b.put(tag(serviceNonce, b.array()));
        String mine = HexFormat.of().formatHex(b.array());
        return mine + " " + ServiceProof.serverProof(secret.get(), serviceNonce, mine);
    }

    /**
     * Checks a registration's proof, {@code "SERVERNONCE SERVICENONCE PROOF"}.
     *
     * @throws SecurityException when it does not prove the secret for this challenge, name and stub;
     *         a message that says "register again" is one the service retries
     */
    public Accepted verify(String proof, String serviceName, Remote stub) {
        String[] w = proof == null ? new String[0] : proof.split(" ");
        if (w.length != 3 || !ServiceProof.isNonce(w[0]) || !ServiceProof.isNonce(w[1])) {
            Audit.log(true, "register-refused", "service", serviceName, "reason", "no-challenge-proof");
            throw new SecurityException("no proof of the service secret: this service is older than the server"
                    + " or does not hold DATA/service.secret (give it with --secret-file)");
        }
        byte[] nv = HexFormat.of().parseHex(w[0]);
        long expires = (ByteBuffer.wrap(nv).getInt() & 0xffffffffL) * 1000;
        byte[] tag = Arrays.copyOfRange(nv, 8, 16);
        if (!MessageDigest.isEqual(tag, tag(w[1], nv)) || expires < System.currentTimeMillis() || isUsed(w[0])) {
            Audit.log(true, "register-refused", "service", serviceName, "reason", "unknown-or-used-challenge");
            throw new SecurityException("the registration's challenge is unknown, used or expired; register again");
        }
        String s = secret.get();
        if (serviceName == null || stub == null || !ServiceProof.same(w[2], ServiceProof.serviceProof(s, w[1], w[0], serviceName, stub))) {
            Audit.log(true, "register-refused", "service", serviceName, "reason", "wrong-secret");
            throw new SecurityException("wrong service secret: give the server's DATA/service.secret with --secret-file");
        }
        if (!use(w[0], expires)) {
            Audit.log(true, "register-refused", "service", serviceName, "reason", "unknown-or-used-challenge");
            throw new SecurityException("the registration's challenge is unknown, used or expired; register again");
        }
        Audit.log(false, "register", "service", serviceName);
        return new Accepted(ServiceProof.token(s, w[1], w[0]), ServiceProof.serverProof(s, w[0], w[1]));
    }

    private synchronized boolean isUsed(String serverNonce) {
        return used.containsKey(serverNonce);
    }

    /** Marks a server nonce used; false when it already was (two registrations raced with one proof). */
    private synchronized boolean use(String serverNonce, long expires) {
        long now = System.currentTimeMillis();
        if (used.size() >= MAX_USED) {
            used.values().removeIf(e -> e < now);
        }
        if (used.size() >= MAX_USED) {
            throw new SecurityException("more than " + MAX_USED + " registrations in a minute; register again in a minute");
        }
        return used.putIfAbsent(serverNonce, expires) == null;
    }

    /** The first 8 bytes of HMAC(key, service nonce, expiry and random of the server nonce). */
    private byte[] tag(String serviceNonce, byte[] serverNonce) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key, "HmacSHA256"));
            mac.update(serviceNonce.getBytes(StandardCharsets.US_ASCII));
            mac.update(serverNonce, 0, 8);
            return Arrays.copyOf(mac.doFinal(), 8);
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("HmacSHA256 is part of every JDK", e);
        }
    }
}
