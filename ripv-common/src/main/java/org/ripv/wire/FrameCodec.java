package org.ripv.wire;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InvalidObjectException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import org.ripv.messages.Message;
import org.ripv.messages.PackedRows;
import org.ripv.messages.SerializedMessages;
import org.ripv.messages.TableResult;

/**
 * The socket protocol between clients and the server (docs/protocol.md). After a greeting of
 * {@link #MAGIC} and a version number each way, every message is one frame: a four-byte
 * big-endian length, then that many bytes holding one serialized {@link Message}. Each frame is
 * read with its own {@link ObjectInputStream} and {@link WireFilter}, so the filter's limits
 * apply per message and a long-lived connection is never refused for its age. A message without
 * attachment or result is written and read as the same bytes without the streams
 * ({@link SerializedMessages}), its classes judged by the same filter.
 */
public final class FrameCodec {
    /** The greeting's first four bytes. */
    public static final byte[] MAGIC = "RIPV".getBytes(StandardCharsets.US_ASCII);
    /** 2 since PackedMessage became Externalizable (docs/protocol.md): a version-1 peer could not read it. */
    public static final int VERSION = 2;
    /** The default limit on one frame. */
    public static final int DEFAULT_MAX_FRAME = 16 * 1024 * 1024;

    private final int maxFrame;
    private final WireFilter filter;

    public FrameCodec(int maxFrame) {
        if (maxFrame < 1024) {
            throw new IllegalArgumentException("a frame limit under 1 KiB is too small: " + maxFrame);
        }
        this.maxFrame = maxFrame;
        this.filter = WireFilter.forFrames(maxFrame);
    }

    public int maxFrame() {
        return maxFrame;
    }

    /** Writes the greeting. */
    public static void writeGreeting(DataOutputStream out) throws IOException {
        out.write(MAGIC);
        out.writeInt(VERSION);
        out.flush();
    }

    /** Reads and checks the greeting. */
    public static void readGreeting(DataInputStream in) throws IOException {
        byte[] magic = new byte[4];
        in.readFully(magic);
        if (!Arrays.equals(magic, MAGIC)) {
            throw new ProtocolException("not a RIPV peer: greeting began " + Arrays.toString(magic));
        }
        int version = in.readInt();
        if (version != VERSION) {
            throw new ProtocolException("protocol version " + version + " is not supported (this side speaks " + VERSION + ")");
        }
    }

    /** Serializes one message into a frame's body. */
    public byte[] encode(Message m) throws IOException {
        byte[] plain = SerializedMessages.serialize(m); // the same bytes, without a stream for them
        if (plain != null) {
            checkSize(plain.length);
            return plain;
        }
        ByteArrayOutputStream body = streamed(m);
        checkSize(body.size());
        return body.toByteArray();
    }

    /** Writes one frame and flushes. The caller serializes access to the stream. */
    public void write(DataOutputStream out, Message m) throws IOException {
        writeNoFlush(out, m);
        out.flush();
    }

    /** Writes one frame without flushing, for a writer that flushes when its queue runs dry. */
    public void writeNoFlush(DataOutputStream out, Message m) throws IOException {
        byte[] plain = SerializedMessages.serialize(m);
        if (plain != null) {
            checkSize(plain.length);
            out.writeInt(plain.length);
            out.write(plain);
            return;
        }
        ByteArrayOutputStream body = streamed(m);
        checkSize(body.size());
        out.writeInt(body.size());
        body.writeTo(out); // no copy of the body (a page of a query is most of a megabyte)
    }

    private void checkSize(int length) throws ProtocolException {
        if (length > maxFrame) {
            throw new ProtocolException("a message of " + length + " bytes is over the frame limit of " + maxFrame);
        }
    }

    private static ByteArrayOutputStream streamed(Message m) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(sizeHint(m));
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(m);
        }
        return bytes;
    }

    /**
     * Room for the message's bytes from the start: a page of rows (issue 38) grown by doubling
     * from 512 bytes was copied a dozen times and ended in an array twice its size.
     */
    private static int sizeHint(Message m) {
        if (m.footer() != null && m.footer().result() instanceof TableResult t && t.rows() instanceof PackedRows p) {
            return p.bytes() + 8192 + 3 * (t.query().length() + (m.header().body() == null ? 0 : m.header().body().length()));
        }
        return 512;
    }

    /**
     * Reads one frame and the message in it.
     *
     * @throws EOFException      when the peer closed the connection between frames
     * @throws ProtocolException for anything that is not a well-formed, allowed message
     */
    public Message read(DataInputStream in) throws IOException {
        return readBody(in, in.readInt());
    }

    /** Reads a frame's body once its length has been read (so the caller can time the two apart). */
    public Message readBody(DataInputStream in, int length) throws IOException {
        if (length <= 0 || length > maxFrame) {
            throw new ProtocolException("frame length " + length + " outside 1.." + maxFrame);
        }
        byte[] body = new byte[length];
        in.readFully(body);
        return decode(body);
    }

    /** Deserializes a frame's body, turning every failure a hostile stream can cause into one exception. */
    public Message decode(byte[] body) throws ProtocolException {
        try {
            Message plain = SerializedMessages.deserialize(body, filter); // the common shape, judged by the same filter
            if (plain != null) {
                return plain;
            }
        } catch (InvalidObjectException | RuntimeException e) {
            throw new ProtocolException("rejected a malformed or disallowed message: " + e, e);
        }
        try (ObjectInputStream ois = new ObjectInputStream(new ByteArrayInputStream(body))) {
            ois.setObjectInputFilter(filter);
            Object o = ois.readObject();
            if (!(o instanceof Message m)) {
                throw new ProtocolException("a frame held " + (o == null ? "null" : o.getClass().getName()) + ", not a message");
            }
            if (ois.read() != -1) {
                throw new ProtocolException("trailing bytes after the message in a frame");
            }
            return m;
        } catch (ProtocolException e) {
            throw e;
        } catch (Exception | StackOverflowError | OutOfMemoryError e) {
            // A crafted stream can make ObjectInputStream throw almost anything (NPE, ClassCast,
            // IllegalState, IllegalArgument...): all of it means a bad frame, never a dead server.
            throw new ProtocolException("rejected a malformed or disallowed message: " + e, e);
        }
    }

    /** Helper for callers writing raw frames (tests of hostile input). */
    public static void writeRawFrame(OutputStream out, byte[] body) throws IOException {
        DataOutputStream d = new DataOutputStream(out);
        d.writeInt(body.length);
        d.write(body);
        d.flush();
    }
}
