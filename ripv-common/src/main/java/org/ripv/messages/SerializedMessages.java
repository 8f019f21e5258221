package org.ripv.messages;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InvalidObjectException;
import java.io.ObjectInputFilter;
import java.io.ObjectOutputStream;
import java.util.Arrays;

/**
 * The Java-serialized form of a message without attachment or typed result — nearly every
 * request and reply — written and read without building an {@link ObjectOutputStream} or
 * {@link java.io.ObjectInputStream} for it. Those streams cost more than the message itself (their
 * buffers and handle tables are allocated anew for every frame, and the class descriptors parsed
 * again), yet such a message's stream is always the same bytes around its packed fields.
 *
 * <p>The bytes are exactly what {@code ObjectOutputStream.writeObject(message)} writes: the
 * constant parts are taken from ObjectOutputStream itself when this class loads, and checked
 * against it for a sample; if anything differs (another JDK), both fast paths stay off and every
 * message goes through the streams. Reading judges the two classes the stream names
 * ({@link PackedMessage} and {@code byte[]}) with the caller's deserialization filter, as
 * {@code ObjectInputStream} would, and rebuilds the message through the same validating
 * {@code readResolve}; anything that is not exactly this shape is left to the streams.
 */
public final class SerializedMessages {
    private static final byte TC_NULL = 0x70;
    /** The stream header and PackedMessage's class descriptor, up to its first field's value. */
    private static final byte[] HEAD;
    /** A byte array's start: TC_ARRAY and byte[]'s class descriptor, before the length. */
    private static final byte[] ARRAY;
    private static final boolean ON;

    static {
        byte[] head = null;
        byte[] array = null;
        boolean on = false;
        try {
            byte[] a = streamed(new PackedMessage((byte) 0x11, new byte[0], null, null));
            byte[] b = streamed(new PackedMessage((byte) 0x22, new byte[0], null, null));
            int i = 0;
            while (i < a.length && i < b.length && a[i] == b[i]) {
                i++;
            }
            // a = HEAD, kind, TC_NULL (attachment), ARRAY, length 0 (4 bytes), TC_NULL (result)
            if (i + 7 <= a.length && a[i] == 0x11 && a[i + 1] == TC_NULL && a[a.length - 1] == TC_NULL) {
                head = Arrays.copyOf(a, i);
                array = Arrays.copyOfRange(a, i + 2, a.length - 5);
                Message sample = new OutgoingServerMessage(new Header(7, new IdBadge("100001", "u"), java.util.List.of("r"),
                        "<S>::<h>", "<S>::<h>X", "dir ü", Priority.URGENT, null), Footer.ok("100100", "text", null).via("<S>::<h>"));
                on = Arrays.equals(write(sample, head, array), streamed(sample));
            }
        } catch (IOException | RuntimeException e) {
            on = false;
        }
        HEAD = head;
        ARRAY = array;
        ON = on;
    }

    private SerializedMessages() {}

    /**
     * The serialized stream of {@code m} as {@code ObjectOutputStream} would write it, or null when
     * the message carries an attachment or a result (then serialize it with the stream).
     */
    public static byte[] serialize(Message m) {
        if (!ON || m.header().attachment() != null || m.footer().result() != null) {
            return null;
        }
        return write(m, HEAD, ARRAY);
    }

    private static byte[] write(Message m, byte[] head, byte[] array) {
        PackedMessage p = PackedMessage.pack(m);
        byte[] fields = p.fields();
        byte[] out = new byte[head.length + 2 + array.length + 4 + fields.length + 1];
        int at = 0;
        System.arraycopy(head, 0, out, at, head.length);
        at += head.length;
        out[at++] = p.kind();
        out[at++] = TC_NULL;
        System.arraycopy(array, 0, out, at, array.length);
        at += array.length;
        int n = fields.length;
        out[at++] = (byte) (n >>> 24);
        out[at++] = (byte) (n >>> 16);
        out[at++] = (byte) (n >>> 8);
        out[at++] = (byte) n;
        System.arraycopy(fields, 0, out, at, n);
        at += n;
        out[at] = TC_NULL;
        return out;
    }

    /**
     * The message in {@code body} when it is a message without attachment or result and
     * {@code filter} allows its classes; null when the stream has any other shape or the filter
     * does not allow it (then read it with an {@code ObjectInputStream} under the same filter,
     * which gives the precise refusal).
     *
     * @throws InvalidObjectException when the stream has this shape but its packed fields are
     *                                malformed
     */
    public static Message deserialize(byte[] body, ObjectInputFilter filter) throws InvalidObjectException {
        if (!ON) {
            return null;
        }
        int fixed = HEAD.length + 2 + ARRAY.length + 4 + 1;
        if (body.length < fixed || !Arrays.equals(body, 0, HEAD.length, HEAD, 0, HEAD.length)) {
            return null;
        }
        int at = HEAD.length;
        byte kind = body[at++];
        if (body[at++] != TC_NULL || !Arrays.equals(body, at, at + ARRAY.length, ARRAY, 0, ARRAY.length)) {
            return null;
        }
        at += ARRAY.length;
        int n = (body[at] & 0xff) << 24 | (body[at + 1] & 0xff) << 16 | (body[at + 2] & 0xff) << 8 | body[at + 3] & 0xff;
        at += 4;
        if (n != body.length - fixed || body[body.length - 1] != TC_NULL) {
            return null;
        }
        if (filter != null && (judged(filter, PackedMessage.class, -1, 1, 1, HEAD.length) != ObjectInputFilter.Status.ALLOWED
                || judged(filter, byte[].class, n, 2, 2, body.length) != ObjectInputFilter.Status.ALLOWED)) {
            return null;
        }
        return new PackedMessage(kind, Arrays.copyOfRange(body, at, at + n), null, null).resolve();
    }

    private static ObjectInputFilter.Status judged(ObjectInputFilter filter, Class<?> c, long arrayLength, long depth,
                                                   long references, long streamBytes) {
        return filter.checkInput(new ObjectInputFilter.FilterInfo() {
            @Override
            public Class<?> serialClass() {
                return c;
            }

            @Override
            public long arrayLength() {
                return arrayLength;
            }

            @Override
            public long depth() {
                return depth;
            }

            @Override
            public long references() {
                return references;
            }

            @Override
            public long streamBytes() {
                return streamBytes;
            }
        });
    }

    private static byte[] streamed(Object o) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(o);
        }
        return bytes.toByteArray();
    }
}
