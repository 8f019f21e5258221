package org.ripv.messages;

import java.io.Externalizable;
import java.io.IOException;
import java.io.InputStream;
import java.io.InvalidObjectException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.io.ObjectStreamException;
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
        // Straight into one array of the exact size: no stream, no buffer grown and copied.
        byte[][] texts = new byte[10 + h.roles().size() + f.route().size()][];
        int n = 0;
        texts[n++] = utf8(h.origin().clientId());
        texts[n++] = utf8(h.origin().user());
        for (String r : h.roles()) {
            texts[n++] = utf8(r);
        }
        texts[n++] = utf8(h.serviceDestination());
        texts[n++] = utf8(h.mailboxAddress());
        texts[n++] = utf8(h.body());
        texts[n++] = utf8(f.serviceId());
        texts[n++] = utf8(f.errorCode().name());
        for (String r : f.route()) {
            texts[n++] = utf8(r);
        }
        texts[n++] = utf8(f.replyText());
        checkListSize(h.roles().size());
        checkListSize(f.route().size());
        int size = 8 + 1 + 1 + 1 + 1 + 4 * n;
        for (int i = 0; i < n; i++) {
            size += texts[i].length;
        }
        Out out = new Out(new byte[size]);
        int t = 0;
        out.putLong(h.messageId());
        out.putText(texts[t++]);
        out.putText(texts[t++]);
        out.put(h.roles().size());
        for (int i = 0; i < h.roles().size(); i++) {
            out.putText(texts[t++]);
        }
        out.putText(texts[t++]);
        out.putText(texts[t++]);
        out.putText(texts[t++]);
        out.put(h.priority().ordinal());
        out.putText(texts[t++]);
        out.put(f.status().ordinal());
        out.putText(texts[t++]);
        out.put(f.route().size());
        for (int i = 0; i < f.route().size(); i++) {
            out.putText(texts[t++]);
        }
        out.putText(texts[t]);
        return new PackedMessage(kind, out.bytes, h.attachment(), f.result());
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
            In in = new In(fields);
            long id = in.getLong();
            IdBadge origin = new IdBadge(in.text(), in.text());
            List<String> roles = in.list();
            String destination = in.text();
            String mailbox = in.text();
            String body = in.text();
            Priority priority = PRIORITIES[index(in.get(), PRIORITIES.length)];
            String sid = in.text();
            Status status = STATUSES[index(in.get(), STATUSES.length)];
            ErrorCode code = ErrorCode.valueOf(in.text());
            List<String> route = in.list();
            String reply = in.text();
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

    private static byte[] utf8(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    private static void checkListSize(int n) {
        if (n > MAX_LIST) {
            throw new UncheckedIOException(new java.io.IOException(
                    "a list of " + n + " is longer than a message may carry (" + MAX_LIST + ")"));
        }
    }

    /** Big-endian writes into an array sized beforehand. */
    private static final class Out {
        final byte[] bytes;
        int pos;

        Out(byte[] bytes) {
            this.bytes = bytes;
        }

        void put(int b) {
            bytes[pos++] = (byte) b;
        }

        void putInt(int v) {
            bytes[pos++] = (byte) (v >>> 24);
            bytes[pos++] = (byte) (v >>> 16);
            bytes[pos++] = (byte) (v >>> 8);
            bytes[pos++] = (byte) v;
        }

        void putLong(long v) {
            putInt((int) (v >>> 32));
            putInt((int) v);
        }

        void putText(byte[] b) {
            putInt(b.length);
            System.arraycopy(b, 0, bytes, pos, b.length);
            pos += b.length;
        }
    }

    /** Reads the fields in place, every length checked against the bytes left. */
    private static final class In {
        private final byte[] bytes;
        private int pos;

        In(byte[] bytes) {
            this.bytes = bytes;
        }

        int remaining() {
            return bytes.length - pos;
        }

        private void need(int n) throws InvalidObjectException {
            if (remaining() < n) {
                throw new InvalidObjectException("a packed message cut short");
            }
        }

        int get() throws InvalidObjectException {
            need(1);
            return bytes[pos++] & 0xff;
        }

        int getInt() throws InvalidObjectException {
            need(4);
            int v = (bytes[pos] & 0xff) << 24 | (bytes[pos + 1] & 0xff) << 16 | (bytes[pos + 2] & 0xff) << 8 | bytes[pos + 3] & 0xff;
            pos += 4;
            return v;
        }

        long getLong() throws InvalidObjectException {
            long high = getInt();
            return high << 32 | getInt() & 0xffffffffL;
        }

        String text() throws InvalidObjectException {
            int n = getInt();
            if (n < 0 || n > remaining()) {
                throw new InvalidObjectException("a text of " + n + " bytes where " + remaining() + " remain");
            }
            String s = new String(bytes, pos, n, StandardCharsets.UTF_8);
            pos += n;
            return s;
        }

        List<String> list() throws InvalidObjectException {
            int n = get();
            List<String> l = new ArrayList<>(n);
            for (int i = 0; i < n; i++) {
                l.add(text());
            }
            return l;
        }
    }
}
