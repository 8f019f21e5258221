package org.ripv.messages;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InvalidObjectException;
import java.io.ObjectStreamException;
import java.io.Serializable;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * The wire form of every {@link Message}: the header's and footer's plain fields packed into one
 * byte array, with only the attachment and the typed result as objects of their own. Java
 * serialization of the nested records, enums and lists cost most of a round trip's CPU; this
 * costs a fraction, on the client socket and on RMI alike. Reading checks every length against
 * the bytes present and rebuilds the message through its validating constructors.
 */
final class PackedMessage implements Serializable {
    private static final long serialVersionUID = 1L;
    private static final int MAX_LIST = 255;

    private final byte kind;
    private final byte[] fields;
    private final Attachment attachment;
    private final Result result;

    private PackedMessage(byte kind, byte[] fields, Attachment attachment, Result result) {
        this.kind = kind;
        this.fields = fields;
        this.attachment = attachment;
        this.result = result;
    }

    static PackedMessage pack(Message m) {
        byte kind = m instanceof IncomingServerMessage ? (byte) 0 : m instanceof IncomingServiceMessage ? (byte) 1
                : m instanceof OutgoingServiceMessage ? (byte) 2 : (byte) 3;
        Header h = m.header();
        Footer f = m.footer();
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(128 + h.body().length() + f.replyText().length());
        try (DataOutputStream out = new DataOutputStream(bytes)) {
            out.writeLong(h.messageId());
            text(out, h.origin().clientId());
            text(out, h.origin().user());
            list(out, h.roles());
            text(out, h.serviceDestination());
            text(out, h.mailboxAddress());
            text(out, h.body());
            out.writeByte(h.priority().ordinal());
            text(out, f.serviceId());
            out.writeByte(f.status().ordinal());
            text(out, f.errorCode().name());
            list(out, f.route());
            text(out, f.replyText());
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a byte array does not fail
        }
        return new PackedMessage(kind, bytes.toByteArray(), h.attachment(), f.result());
    }

    private Object readResolve() throws ObjectStreamException {
        if (fields == null) {
            throw new InvalidObjectException("a packed message without fields");
        }
        try (DataInputStream in = new DataInputStream(new java.io.ByteArrayInputStream(fields))) {
            long id = in.readLong();
            IdBadge origin = new IdBadge(text(in), text(in));
            List<String> roles = list(in);
            String destination = text(in);
            String mailbox = text(in);
            String body = text(in);
            Priority priority = Priority.values()[index(in.readUnsignedByte(), Priority.values().length)];
            String sid = text(in);
            Status status = Status.values()[index(in.readUnsignedByte(), Status.values().length)];
            ErrorCode code = ErrorCode.valueOf(text(in));
            List<String> route = list(in);
            String reply = text(in);
            if (in.available() != 0) {
                throw new InvalidObjectException("trailing bytes in a packed message");
            }
            Header h = new Header(id, origin, roles, destination, mailbox, body, priority, attachment);
            Footer f = new Footer(sid, status, code, route, reply, result);
            return switch (kind) {
                case 0 -> new IncomingServerMessage(h);
                case 1 -> new IncomingServiceMessage(h);
                case 2 -> new OutgoingServiceMessage(h, f);
                case 3 -> new OutgoingServerMessage(h, f);
                default -> throw new InvalidObjectException("unknown message kind " + kind);
            };
        } catch (InvalidObjectException e) {
            throw e;
        } catch (IOException | RuntimeException e) {
            InvalidObjectException bad = new InvalidObjectException("malformed packed message: " + e.getMessage());
            bad.initCause(e);
            throw bad;
        }
    }

    private static int index(int i, int size) throws InvalidObjectException {
        if (i >= size) {
            throw new InvalidObjectException("enum index " + i + " out of range");
        }
        return i;
    }

    private static void text(DataOutputStream out, String s) throws IOException {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        out.writeInt(b.length);
        out.write(b);
    }

    private static String text(DataInputStream in) throws IOException {
        int n = in.readInt();
        if (n < 0 || n > in.available()) {
            throw new InvalidObjectException("a text of " + n + " bytes where " + in.available() + " remain");
        }
        return new String(in.readNBytes(n), StandardCharsets.UTF_8);
    }

    private static void list(DataOutputStream out, List<String> l) throws IOException {
        if (l.size() > MAX_LIST) {
            throw new IOException("a list of " + l.size() + " is longer than a message may carry (" + MAX_LIST + ")");
        }
        out.writeByte(l.size());
        for (String s : l) {
            text(out, s);
        }
    }

    private static List<String> list(DataInputStream in) throws IOException {
        int n = in.readUnsignedByte();
        if (n > MAX_LIST) {
            throw new InvalidObjectException("a list of " + n + " where at most " + MAX_LIST + " are allowed");
        }
        List<String> l = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            l.add(text(in));
        }
        return l;
    }
}
