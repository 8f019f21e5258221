package org.ripv.outbound;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.HexFormat;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;
import org.ripv.wire.ProtocolException;

/**
 * How a service and the server prove to each other that both know the service secret before an
 * outbound connection carries calls, without the secret ever crossing the wire: the server sends
 * a fresh challenge, the service answers with its name, a challenge of its own and
 * HMAC-SHA256(secret, "service|" + both challenges + name), and the server answers with
 * HMAC-SHA256(secret, "server|" + the same). A replayed or forged answer fails.
 */
public final class OutboundHandshake {
    /** What a service sends first, so that a wrong port fails at once with a clear message. */
    public static final String HELLO = "RIPV-OUTBOUND/1";
    private static final SecureRandom RANDOM = new SecureRandom();
    private static final int MAX_FIELD = 512;

    private OutboundHandshake() {}

    /**
     * The service's side; returns normally when the server proved itself and accepted.
     *
     * @throws SecurityException when the server refused the secret, or could not prove it knows it
     */
    public static void service(DataInputStream in, DataOutputStream out, String secret, String name) throws IOException {
        out.writeUTF(HELLO);
        out.flush();
        String serverNonce = field(in);
        String mine = nonce();
        out.writeUTF(name);
        out.writeUTF(mine);
        out.writeUTF(mac(secret, "service|" + serverNonce + "|" + mine + "|" + name));
        out.flush();
        String answer = field(in);
        if (answer.startsWith("ERR ")) {
            throw new SecurityException(answer.substring(4));
        }
        if (!answer.startsWith("OK ") || !same(answer.substring(3), mac(secret, "server|" + serverNonce + "|" + mine + "|" + name))) {
            throw new SecurityException("the server at the other end did not prove that it knows the service secret");
        }
    }

    /**
     * The server's side.
     *
     * @return the service's name, proven
     * @throws SecurityException when the service's proof is wrong (it has been told)
     */
    public static String server(DataInputStream in, DataOutputStream out, String secret) throws IOException {
        String hello = field(in);
        if (!HELLO.equals(hello)) {
            throw new ProtocolException("not a RIPV service's outbound connection");
        }
        String mine = nonce();
        out.writeUTF(mine);
        out.flush();
        String name = field(in);
        String theirs = field(in);
        String proof = field(in);
        if (theirs.length() < 32 || !same(proof, mac(secret, "service|" + mine + "|" + theirs + "|" + name))) {
            out.writeUTF("ERR wrong service secret: give the server's DATA/service.secret with --secret-file");
            out.flush();
            throw new SecurityException("wrong service secret from " + name);
        }
        out.writeUTF("OK " + mac(secret, "server|" + mine + "|" + theirs + "|" + name));
        out.flush();
        return name;
    }

    private static String field(DataInputStream in) throws IOException {
        String s = in.readUTF();
        if (s.length() > MAX_FIELD) {
            throw new ProtocolException("a handshake field of " + s.length() + " characters");
        }
        return s;
    }

    private static String nonce() {
        byte[] b = new byte[32];
        RANDOM.nextBytes(b);
        return HexFormat.of().formatHex(b);
    }

    static String mac(String secret, String text) {
        try {
            Mac m = Mac.getInstance("HmacSHA256");
            m.init(new SecretKeySpec(secret.getBytes(StandardCharsets.UTF_8), "HmacSHA256"));
            return HexFormat.of().formatHex(m.doFinal(text.getBytes(StandardCharsets.UTF_8)));
        } catch (GeneralSecurityException e) {
            throw new IllegalStateException("HmacSHA256 is missing from this JDK", e);
        }
    }

    private static boolean same(String a, String b) {
        return MessageDigest.isEqual(a.getBytes(StandardCharsets.UTF_8), b.getBytes(StandardCharsets.UTF_8));
    }
}
