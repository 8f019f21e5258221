package org.ripv.services.simulator;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import org.ripv.services.serial.FilterLink;
import org.ripv.services.serial.Link;

/**
 * The simulator's view of its link: bytes the shell read past the end of a command line are
 * pushed back, so a YMODEM 'C' that arrives right behind {@code ys NAME} reaches the sender.
 */
final class ShellLink extends FilterLink {
    private byte[] pending = new byte[0];
    private int position;

    ShellLink(Link link) {
        super(link);
    }

    void unread(byte[] bytes, int offset, int len) {
        byte[] rest = new byte[len + pending.length - position];
        System.arraycopy(bytes, offset, rest, 0, len);
        System.arraycopy(pending, position, rest, len, pending.length - position);
        pending = rest;
        position = 0;
    }

    @Override
    public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
        if (position < pending.length) {
            int n = Math.min(len, pending.length - position);
            System.arraycopy(pending, position, buffer, offset, n);
            position += n;
            return n;
        }
        return super.read(buffer, offset, len, timeoutMillis);
    }

    /** Writes text as the vehicle's terminal does (ISO-8859-1) and flushes it. */
    void say(String text) throws IOException {
        byte[] bytes = text.getBytes(StandardCharsets.ISO_8859_1);
        write(bytes, 0, bytes.length);
        flush();
    }
}
