package org.ripv.services.serial.ymodem;

import java.io.EOFException;
import java.io.IOException;

/**
 * The two directions of a byte link as YMODEM needs them: a read that waits at most a given
 * time, and a write. Serial ports, TCP sockets and in-memory pipes all implement it.
 */
public interface ByteLink {

    /**
     * Reads up to {@code len} bytes, waiting at most {@code timeoutMillis} for the first one.
     *
     * @return the number of bytes read, 0 when nothing arrived in time
     * @throws EOFException when the far end has gone (closed socket, vanished pty peer)
     */
    int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException;

    /** Writes all of the bytes (blocking while the line is busy). */
    void write(byte[] buffer, int offset, int len) throws IOException;

    /** Pushes out anything buffered on this side. */
    default void flush() throws IOException {
    }

    /**
     * True when the link holds far more than the line carries in a frame timeout: a TCP socket in
     * front of a modem takes a whole file at once while the line needs minutes for it. A ZMODEM
     * sender on such a link keeps in step with its receiver's acknowledgements (a window), or its
     * wait for the answer to the end of the file would outlast the timeout. A serial port's few
     * buffered bytes keep a sender in step by themselves.
     */
    default boolean buffersDeeply() {
        return false;
    }

    /** Writes all of {@code bytes}. */
    default void write(byte[] bytes) throws IOException {
        write(bytes, 0, bytes.length);
    }
}
