package org.ripv.services.ingest;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * Reads a stream line by line into one reused byte buffer, never holding more than one line
 * (at most a given length) in memory, and counting lines. Line ends are LF or CRLF.
 */
final class LineReader {
    private final InputStream in;
    private final byte[] buf = new byte[1 << 16];
    private int pos;
    private int limit;
    private byte[] line = new byte[4096];
    private int length;
    private long number;
    private boolean lastHadEnd = true;

    LineReader(InputStream in) {
        this.in = in;
    }

    /**
     * Reads the next line, of at most {@code maxLength} bytes. False at the end of the stream.
     *
     * @throws DbaFormatException when the line is longer
     */
    boolean next(int maxLength) throws IOException, DbaFormatException {
        length = 0;
        boolean any = false;
        while (true) {
            if (pos == limit) {
                limit = in.read(buf, 0, buf.length);
                pos = 0;
                if (limit <= 0) {
                    limit = 0;
                    if (any) {
                        number++;
                        lastHadEnd = false;
                        trimCr();
                        return true;
                    }
                    return false;
                }
            }
            any = true;
            int start = pos;
            while (pos < limit && buf[pos] != '\n') {
                pos++;
            }
            append(start, pos - start, maxLength);
            if (pos < limit) {
                pos++; // the '\n'
                number++;
                trimCr();
                return true;
            }
        }
    }

    private void append(int from, int n, int maxLength) throws DbaFormatException {
        if (length + n > maxLength) {
            throw new DbaFormatException(number + 1, "the line is longer than " + maxLength + " bytes");
        }
        if (length + n > line.length) {
            byte[] bigger = new byte[Math.max(line.length * 2, length + n)];
            System.arraycopy(line, 0, bigger, 0, length);
            line = bigger;
        }
        System.arraycopy(buf, from, line, length, n);
        length += n;
    }

    private void trimCr() {
        if (length > 0 && line[length - 1] == '\r') {
            length--;
        }
    }

    /** The bytes of the current line (valid up to {@link #length()}). */
    byte[] bytes() {
        return line;
    }

    int length() {
        return length;
    }

    /** The current line's 1-based number. */
    long number() {
        return number;
    }

    /** False when the last line read ended at the end of the stream without a line end. */
    boolean lastHadEnd() {
        return lastHadEnd;
    }

    /** The current line as text (header and label lines only: rows are parsed from the bytes). */
    String text() {
        return new String(line, 0, length, StandardCharsets.ISO_8859_1);
    }
}
