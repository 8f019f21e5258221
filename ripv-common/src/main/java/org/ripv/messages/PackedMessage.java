package org.ripv.messages;

import java.io.Externalizable;
import java.io.IOException;
import java.io.InputStream;
import java.io.InvalidObjectException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.io.ObjectStreamException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

/**
 * The wire form of every {@link Message}: the header's and footer's plain fields packed into one
 * byte array, with only the attachment and the typed result as objects of their own. Java
 * serialization of the nested records, enums and lists cost most of a round trip's CPU; this
 * costs a fraction, on the client socket and on RMI alike. Reading checks every length against
 * the bytes present and rebuilds the message through its validating constructors.
 *
 * <p>Externalizable, so that its class descriptor names no fields: every RMI call and frame
 * writes and parses the descriptor anew, and the four fields' names and types, with the byte
 * array's own descriptor, were most of what a call spent on the message.
 */
final class PackedMessage implements Externalizable {
    private static final long serialVersionUID = 2L;
    private static final int MAX_LIST = 255;
    private static final int HAS_ATTACHMENT = 1;
    private static final int HAS_RESULT = 2;

    private byte kind;
    private byte[] fields;
    private Attachment attachment;
    private Result result;

    /** For deserialization only ({@link #readExternal} fills it in). */
    public PackedMessage() {
    }

    PackedMessage(byte kind, byte[] fields, Attachment attachment, Result result) {
        this.kind = kind;
        this.fields = fields;
        this.attachment = attachment;
        this.result = result;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeByte(kind);
        out.writeInt(fields == null ? -1 : fields.length);
        if (fields != null) {
            out.write(fields);
        }
        out.writeByte((attachment == null ? 0 : HAS_ATTACHMENT) | (result == null ? 0 : HAS_RESULT));
        if (attachment != null) {
            out.writeObject(attachment);
        }
        if (result != null) {
            out.writeObject(result);
        }
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException, ClassNotFoundException {
        kind = in.readByte();
        int n = in.readInt();
        if (n < -1) {
            throw new InvalidObjectException("a packed message of " + n + " bytes");
        }
        if (n >= 0) {
            // Read what is there rather than allocate what the length claims: a lying length
            // costs the liar its own bytes, not the reader an array of 2 GB.
            byte[] b = in instanceof InputStream stream ? stream.readNBytes(n) : new byte[0];
            if (b.length != n) {
                throw new InvalidObjectException("a packed message cut short: " + b.length + " of " + n + " bytes");
            }
            fields = b;
        }
        int has = in.readUnsignedByte();
        if ((has & ~(HAS_ATTACHMENT | HAS_RESULT)) != 0) {
            throw new InvalidObjectException("unknown flags " + has + " in a packed message");
        }
        if ((has & HAS_ATTACHMENT) != 0) {
            attachment = typed(in.readObject(), Attachment.class);
        }
        if ((has & HAS_RESULT) != 0) {
            result = typed(in.readObject(), Result.class);
        }
    }

    private static <T> T typed(Object o, Class<T> type) throws InvalidObjectException {
        if (!type.isInstance(o)) {
            throw new InvalidObjectException("a packed message holds " + (o == null ? "null" : o.getClass().getName())
                    + " where " + type.getSimpleName() + " belongs");
        }
        return type.cast(o);
    }

    static PackedMessage pack(Message m) {
        byte kind = m instanceof IncomingServerMessage ? (byte) 0 : m instanceof IncomingServiceMessage ? (byte) 1
                : m instanceof OutgoingServiceMessage ? (byte) 2 : (byte) 3;
        Header h = m.header();
        Footer f = m.footer();
        checkListSize(h.roles().size());
        checkListSize(f.route().size());
        PackedBytes.Writer out = new PackedBytes.Writer(128 + h.body().length() + f.replyText().length(), "a message");
        out.writeLong(h.messageId());
        out.writeString(h.origin().clientId());
        out.writeString(h.origin().user());
        list(out, h.roles());
        out.writeString(h.serviceDestination());
        out.writeString(h.mailboxAddress());
        out.writeString(h.body());
        out.writeByte(h.priority().ordinal());
        out.writeString(f.serviceId());
        out.writeByte(f.status().ordinal());
        out.writeString(f.errorCode().name());
        list(out, f.route());
        out.writeString(f.replyText());
        return new PackedMessage(kind, out.toArray(), h.attachment(), f.result());
    }

    byte kind() {
        return kind;
    }

    byte[] fields() {
        return fields;
    }

    private Object readResolve() throws ObjectStreamException {
        return resolve();
    }

    /** The message these fields describe, checked as on reading. */
    Message resolve() throws InvalidObjectException {
        if (fields == null) {
            throw new InvalidObjectException("a packed message without fields");
        }
        try {
            PackedBytes.Reader in = new PackedBytes.Reader(fields, "a packed message");
            long id = in.readLong();
            IdBadge origin = new IdBadge(text(in), text(in));
            List<String> roles = list(in);
            String destination = text(in);
            String mailbox = text(in);
            String body = text(in);
            Priority priority = PRIORITIES[index(in.readByte(), PRIORITIES.length)];
            String sid = text(in);
            Status status = STATUSES[index(in.readByte(), STATUSES.length)];
            ErrorCode code = ErrorCode.valueOf(text(in));
            List<String> route = list(in);
            String reply = text(in);
            if (in.remaining() != 0) {
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
        } catch (RuntimeException e) {
            InvalidObjectException bad = new InvalidObjectException("malformed packed message: " + e.getMessage());
            bad.initCause(e);
            throw bad;
        }
    }

    /** The enums' values, copied once rather than on every message. */
    private static final Priority[] PRIORITIES = Priority.values();
    private static final Status[] STATUSES = Status.values();

    private static int index(int i, int size) throws InvalidObjectException {
        if (i >= size) {
            throw new InvalidObjectException("enum index " + i + " out of range");
        }
        return i;
    }

    private static void checkListSize(int n) {
        if (n > MAX_LIST) {
            throw new UncheckedIOException(new IOException(
                    "a list of " + n + " is longer than a message may carry (" + MAX_LIST + ")"));
        }
    }

    private static void list(PackedBytes.Writer out, List<String> l) {
        out.writeByte(l.size());
        for (String s : l) {
            out.writeString(s);
        }
    }

    /** A text of the message: never absent (the -1 length PackedBytes reads as null is refused). */
    private static String text(PackedBytes.Reader in) throws InvalidObjectException {
        String s = in.readString();
        if (s == null) {
            throw new InvalidObjectException("a packed message with a text missing");
        }
        return s;
    }

    private static List<String> list(PackedBytes.Reader in) throws InvalidObjectException {
        int n = in.readByte();
        List<String> l = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            l.add(text(in));
        }
        return l;
    }
}
