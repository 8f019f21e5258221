package org.ripv.handout;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Base64;
import java.util.HexFormat;
import java.util.regex.Pattern;
import org.ripv.security.ServiceProof;

/**
 * The server's permission for one service to read one file a second service holds: who holds it
 * ({@code source}), who may ingest it ({@code destination}), the file's SHA-256 and size as the
 * server received them, until when, and a nonce that makes the ticket one of a kind. The MAC is
 * {@link ServiceProof#handoutProof} keyed with the holder's session token: the holder checks it
 * without asking the server, and nobody without that token can make one.
 *
 * <p>On the wire it is one line of at most {@link #MAX_TEXT} characters:
 * {@code ripv-handout-1 SOURCE DESTINATION SHA256 SIZE EXPIRES NONCE MAC}, the two names in
 * URL-safe Base64 so that nothing in a name can shift the fields.
 */
public record HandoutTicket(String source, String destination, String sha256, long size, long expiresAt,
                            String nonce, String mac) {
    static final String VERSION = "ripv-handout-1";
    /** The longest ticket text anyone parses. */
    public static final int MAX_TEXT = 1024;
    private static final Pattern HEX64 = Pattern.compile("[0-9a-f]{64}");
    private static final Base64.Encoder B64 = Base64.getUrlEncoder().withoutPadding();

    /** Signs a ticket with the holder's session token. */
    public static HandoutTicket sign(String sourceToken, String source, String destination, byte[] data, long expiresAt) {
        String sha = sha256(data);
        String nonce = ServiceProof.nonce();
        return new HandoutTicket(source, destination, sha, data.length, expiresAt, nonce,
                ServiceProof.handoutProof(sourceToken, fields(source, destination, sha, data.length, expiresAt, nonce)));
    }

    /**
     * Reads a ticket's text. Checks only its shape; {@link #verify} checks that the server signed it.
     *
     * @throws HandoutRefused when the text is not a ticket
     */
    public static HandoutTicket parse(String text) throws HandoutRefused {
        if (text == null || text.length() > MAX_TEXT) {
            throw new HandoutRefused("not a handout ticket (missing or longer than " + MAX_TEXT + " characters)");
        }
        String[] f = text.split(" ", -1);
        if (f.length != 8 || !f[0].equals(VERSION)) {
            throw new HandoutRefused("not a handout ticket (expected " + VERSION + " and 7 fields)");
        }
        try {
            String source = new String(Base64.getUrlDecoder().decode(f[1]), StandardCharsets.UTF_8);
            String destination = new String(Base64.getUrlDecoder().decode(f[2]), StandardCharsets.UTF_8);
            long size = Long.parseLong(f[4]);
            long expires = Long.parseLong(f[5]);
            if (!HEX64.matcher(f[3]).matches() || !HEX64.matcher(f[7]).matches() || !ServiceProof.isNonce(f[6]) || size < 0) {
                throw new HandoutRefused("not a handout ticket (a field is malformed)");
            }
            return new HandoutTicket(source, destination, f[3], size, expires, f[6], f[7]);
        } catch (IllegalArgumentException e) {
            throw new HandoutRefused("not a handout ticket (a field is malformed)");
        }
    }

    /**
     * Checks the MAC with the holder's session token and the expiry.
     *
     * @throws HandoutRefused when the server did not sign this ticket for this session, or it expired
     */
    public void verify(String sourceToken, long now) throws HandoutRefused {
        String expected = sourceToken == null ? null
                : ServiceProof.handoutProof(sourceToken, fields(source, destination, sha256, size, expiresAt, nonce));
        if (!ServiceProof.same(expected, mac)) {
            throw new HandoutRefused("the handout ticket is forged, or was signed for an earlier registration of " + source);
        }
        if (now > expiresAt) {
            throw new HandoutRefused("the handout ticket expired");
        }
    }

    /** The text form, as {@link #parse} reads it. */
    public String text() {
        return String.join(" ", VERSION, B64.encodeToString(source.getBytes(StandardCharsets.UTF_8)),
                B64.encodeToString(destination.getBytes(StandardCharsets.UTF_8)), sha256, Long.toString(size),
                Long.toString(expiresAt), nonce, mac);
    }

    /** The SHA-256 of {@code data}, in lower-case hex. */
    public static String sha256(byte[] data) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(data));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this JDK", e);
        }
    }

    private static String[] fields(String source, String destination, String sha, long size, long expires, String nonce) {
        return new String[] {source, destination, sha, Long.toString(size), Long.toString(expires), nonce};
    }

    @Override
    public String toString() {
        return "HandoutTicket[" + source + " -> " + destination + ", " + size + " bytes, " + sha256.substring(0, 12) + "…]";
    }
}
