package org.ripv.messages;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InvalidObjectException;
import java.io.ObjectInputFilter;
import java.io.ObjectOutputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The Java-serialized form of a message without attachment or typed result — nearly every
 * request and reply — written and read without building an {@link ObjectOutputStream} or
 * {@link java.io.ObjectInputStream} for it. Those streams cost more than the message itself (their
 * buffers and handle tables are allocated anew for every frame, and the class descriptors parsed
 * again), yet such a message's stream is always the same bytes around its packed fields.
 *
 * <p>The bytes are exactly what {@code ObjectOutputStream.writeObject(message)} writes: the
 * constant parts are taken from ObjectOutputStream itself when this class loads, and checked
 * against it for samples; if anything differs (another JDK), both fast paths stay off and every
 * message goes through the streams. Reading judges the one class the stream names
 * ({@link PackedMessage}) with the caller's deserialization filter, as {@code ObjectInputStream}
 * would, and rebuilds the message through the same validating {@code readResolve}; anything that
 * is not exactly this shape is left to the streams.
 */
public final class SerializedMessages {
    private static final byte TC_BLOCKDATA = 0x77;
    private static final byte TC_BLOCKDATALONG = 0x7A;
    private static final byte TC_ENDBLOCKDATA = 0x78;
    /** ObjectOutputStream's block size: an externalizable object's data is cut into blocks of this. */
    private static final int BLOCK = 1024;
    /** The stream header and PackedMessage's class descriptor, up to its data's first block. */
    private static final byte[] HEAD;
    private static final boolean ON;

    static {
        byte[] head = null;
        boolean on = false;
        try {
            // HEAD, then one block of kind, length 0 (4 bytes) and flags 0, then the end of the data
            byte[] a = streamed(new PackedMessage((byte) 0x11, new byte[0], null, null));
            int at = a.length - 9;
            if (at > 0 && a[at] == TC_BLOCKDATA && a[at + 1] == 6 && a[at + 2] == 0x11 && a[a.length - 1] == TC_ENDBLOCKDATA) {
                head = Arrays.copyOf(a, at);
                on = true;
                for (Message sample : samples()) {
                    on &= Arrays.equals(write(sample, head), streamed(sample));
                }
            }
        } catch (IOException | RuntimeException e) {
            on = false;
        }
        HEAD = head;
        ON = on;
    }

    /** Messages whose data takes one short block, one long block, and several. */
    private static List<Message> samples() {
        List<Message> out = new ArrayList<>();
        for (int size : new int[] {3, 300, 3000}) {
            out.add(new OutgoingServerMessage(new Header(7, new IdBadge("100001", "u"), List.of("r"), "<S>::<h>",
                    "<S>::<h>X", "dir ü" + "x".repeat(size), Priority.URGENT, null), Footer.ok("100100", "text", null).via("<S>::<h>")));
        }
        return out;
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
        return write(m, HEAD);
    }

    private static byte[] write(Message m, byte[] head) {
        PackedMessage p = PackedMessage.pack(m);
        byte[] fields = p.fields();
        int data = 1 + 4 + fields.length + 1;
        int blocks = (data + BLOCK - 1) / BLOCK;
        int headers = 0;
        for (int b = 0; b < blocks; b++) {
            headers += Math.min(BLOCK, data - b * BLOCK) <= 0xFF ? 2 : 5;
        }
        byte[] content = new byte[data];
        content[0] = p.kind();
        putInt(content, 1, fields.length);
        System.arraycopy(fields, 0, content, 5, fields.length);
        content[data - 1] = 0; // no attachment, no result
        byte[] out = new byte[head.length + headers + data + 1];
        System.arraycopy(head, 0, out, 0, head.length);
        int at = head.length;
        for (int from = 0; from < data; from += BLOCK) {
            int len = Math.min(BLOCK, data - from);
            if (len <= 0xFF) {
                out[at++] = TC_BLOCKDATA;
                out[at++] = (byte) len;
            } else {
                out[at++] = TC_BLOCKDATALONG;
                putInt(out, at, len);
                at += 4;
            }
            System.arraycopy(content, from, out, at, len);
            at += len;
        }
        out[at] = TC_ENDBLOCKDATA;
        return out;
    }

    private static void putInt(byte[] b, int at, int v) {
        b[at] = (byte) (v >>> 24);
        b[at + 1] = (byte) (v >>> 16);
        b[at + 2] = (byte) (v >>> 8);
        b[at + 3] = (byte) v;
    }

    private static int getInt(byte[] b, int at) {
        return (b[at] & 0xff) << 24 | (b[at + 1] & 0xff) << 16 | (b[at + 2] & 0xff) << 8 | b[at + 3] & 0xff;
    }

    /**
     * The message in {@code body} when it is a message without attachment or result and
     * {@code filter} allows its class; null when the stream has any other shape or the filter
     * does not allow it (then read it with an {@code ObjectInputStream} under the same filter,
     * which gives the precise refusal).
     *
     * @throws InvalidObjectException when the stream has this shape but its packed fields are
     *                                malformed
     */
    public static Message deserialize(byte[] body, ObjectInputFilter filter) throws InvalidObjectException {
        if (!ON || body.length < HEAD.length + 2 || !Arrays.equals(body, 0, HEAD.length, HEAD, 0, HEAD.length)) {
            return null;
        }
        // The data blocks' size first, without copying: a frame of another shape (a page of a
        // query, most of a megabyte, carries a result) is left to the stream having cost nothing.
        int size = blocks(body, null);
        if (size < 0) {
            return null;
        }
        byte[] content = new byte[size];
        blocks(body, content);
        if (size < 6) {
            return null;
        }
        int n = getInt(content, 1);
        if (n < 0 || n != size - 6 || content[size - 1] != 0) {
            return null;
        }
        if (filter != null && judged(filter, PackedMessage.class, -1, 1, 1, body.length) != ObjectInputFilter.Status.ALLOWED) {
            return null;
        }
        return new PackedMessage(content[0], Arrays.copyOfRange(content, 5, 5 + n), null, null).resolve();
    }

    /**
     * The size of the data blocks after {@link #HEAD} when they end exactly at the body's end, else
     * -1; copies them, gathered, into {@code into} when it is given.
     */
    private static int blocks(byte[] body, byte[] into) {
        int size = 0;
        int at = HEAD.length;
        while (true) {
            if (at >= body.length) {
                return -1;
            }
            byte tag = body[at++];
            int len;
            if (tag == TC_ENDBLOCKDATA) {
                return at == body.length ? size : -1;
            } else if (tag == TC_BLOCKDATA && at < body.length) {
                len = body[at++] & 0xff;
            } else if (tag == TC_BLOCKDATALONG && at + 4 <= body.length) {
                len = getInt(body, at);
                at += 4;
            } else {
                return -1;
            }
            if (len < 0 || len > body.length - at) {
                return -1;
            }
            if (into != null) {
                System.arraycopy(body, at, into, size, len);
            }
            size += len;
            at += len;
        }
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
