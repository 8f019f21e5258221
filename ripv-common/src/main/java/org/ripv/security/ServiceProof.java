package org.ripv.security;

import java.lang.reflect.Proxy;
import java.nio.charset.StandardCharsets;
import java.rmi.Remote;
import java.rmi.server.RemoteObject;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * The registration handshake between a service and the server, HMAC-SHA256 keyed with the
 * service secret (docs/security.md, "Services and the registry"):
 * <ol>
 *   <li>the service sends a fresh nonce {@code Ns} ({@code GenericRMIInterface.challenge});</li>
 *   <li>the server answers its own nonce {@code Nv} and {@link #serverProof}; a service that finds
 *       the proof wrong is talking to an impostor and sends nothing more;</li>
 *   <li>the service registers with {@link #serviceProof}, which also names the service and its
 *       exported object, so that a relay cannot register itself in the service's place;</li>
 *   <li>both sides derive the session {@link #token} from the two nonces: it never crosses the wire
 *       before it is used, and the secret never does.</li>
 * </ol>
 */
public final class ServiceProof {
    private static final SecureRandom RANDOM = new SecureRandom();
    private static final Pattern ENDPOINT = Pattern.compile("endpoint:\\[([^,\\]]*)");
    private static final Pattern OBJ_NUM = Pattern.compile("objID:\\[(?:[^\\]]*, )?(-?\\d+)\\]");

    private ServiceProof() {}

    /** A fresh random nonce (32 hex digits). */
    public static String nonce() {
        byte[] b = new byte[16];
        RANDOM.nextBytes(b);
        return HexFormat.of().formatHex(b);
    }

    /** The server's answer to a challenge: it knows the secret. */
    public static String serverProof(String secret, String serviceNonce, String serverNonce) {
        return hmac(secret, "ripv-server", serviceNonce, serverNonce);
    }

    /** The service's registration proof, bound to its name and its exported object. */
    public static String serviceProof(String secret, String serviceNonce, String serverNonce, String serviceName, Remote stub) {
        return hmac(secret, "ripv-service", serviceNonce, serverNonce, serviceName, identity(stub));
    }

    /** The session token both sides derive after a successful handshake. */
    public static String token(String secret, String serviceNonce, String serverNonce) {
        return hmac(secret, "ripv-token", serviceNonce, serverNonce);
    }

    /**
     * The MAC of a handout ticket ({@link org.ripv.handout.HandoutTicket}): keyed with the session
     * token of the service that holds the file, which only that service and the server know, so
     * that the service can check a ticket the server signed without asking it.
     */
    public static String handoutProof(String sourceToken, String... fields) {
        String[] parts = new String[fields.length + 1];
        parts[0] = "ripv-handout";
        System.arraycopy(fields, 0, parts, 1, fields.length);
        return hmac(sourceToken, parts);
    }

    /** Compares two proofs in constant time; false for null. */
    public static boolean same(String a, String b) {
        return a != null && b != null
                && MessageDigest.isEqual(a.getBytes(StandardCharsets.UTF_8), b.getBytes(StandardCharsets.UTF_8));
    }

    /**
     * True when a refusal asks to be tried again ("register again", "retry", "try again"): such a
     * refusal comes from a live server that will take the service later, so a service keeps trying.
     */
    public static boolean saysRetry(String refusal) {
        return refusal != null && RETRY.matcher(refusal).find();
    }

    private static final Pattern RETRY = Pattern.compile("\\b(?:register again|retry|try again)\\b", Pattern.CASE_INSENSITIVE);

    /** True when the text is a nonce as {@link #nonce} makes them (so that no one feeds a long string to the HMAC). */
    public static boolean isNonce(String s) {
        return s != null && s.matches("[0-9a-f]{32}");
    }

    /**
     * What identifies an exported object on both ends: its endpoint's host and port and its
     * random object number, read from the stub's reference.
     */
    static String identity(Remote stub) {
        RemoteObject ro = stub instanceof RemoteObject r ? r
                : Proxy.isProxyClass(stub.getClass()) && Proxy.getInvocationHandler(stub) instanceof RemoteObject h ? h : null;
        if (ro == null || ro.getRef() == null) {
            return "";
        }
        String s = ro.getRef().remoteToString();
        Matcher e = ENDPOINT.matcher(s);
        Matcher n = OBJ_NUM.matcher(s);
        return (e.find() ? e.group(1) : "") + "#" + (n.find() ? n.group(1) : "");
    }

    private static String hmac(String secret, String... parts) {
        try {
            Mac mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(secret.getBytes(StandardCharsets.UTF_8), "HmacSHA256"));
            for (String p : parts) {
                mac.update(p.getBytes(StandardCharsets.UTF_8));
                mac.update((byte) 0);
            }
            return HexFormat.of().formatHex(mac.doFinal());
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("HmacSHA256 is missing from this JDK", e);
        }
    }
}
