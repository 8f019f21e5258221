package org.ripv.server.http;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;

/**
 * A streaming reader of a {@code multipart/form-data} body (RFC 7578): parts are read one after
 * another, each body copied to an {@link OutputStream} without holding it in memory.
 */
final class MultipartStream {
    /** Header block of one part is at most this long. */
    static final int MAX_HEADER_BYTES = 16 * 1024;

    /** A malformed body. */
    static final class MalformedException extends IOException {
        private static final long serialVersionUID = 1L;

        MalformedException(String message) {
            super(message);
        }
    }

    /** One part's headers: the form field name and, for a file, its file name. */
    record Part(String fieldName, String fileName, Map<String, String> headers) {
        boolean isFile() {
            return fileName != null;
        }
    }

    private final InputStream in;
    private final byte[] delimiter;
    private final byte[] buf = new byte[64 * 1024];
    private int start;
    private int end;
    private boolean eof;
    private boolean finished;

    MultipartStream(InputStream in, String boundary) {
        this.in = in;
        // Treat the body as if it began with CRLF, so the first boundary looks like every other.
        this.delimiter = ("\r\n--" + boundary).getBytes(StandardCharsets.ISO_8859_1);
        buf[0] = '\r';
        buf[1] = '\n';
        end = 2;
    }

    /** The boundary from a Content-Type header, or null when it is not multipart/form-data. */
    static String boundary(String contentType) {
        if (contentType == null || !contentType.toLowerCase(Locale.ROOT).startsWith("multipart/form-data")) {
            return null;
        }
        for (String p : contentType.split(";")) {
            String t = p.trim();
            if (t.toLowerCase(Locale.ROOT).startsWith("boundary=")) {
                String b = t.substring("boundary=".length());
                if (b.length() >= 2 && b.startsWith("\"") && b.endsWith("\"")) {
                    b = b.substring(1, b.length() - 1);
                }
                return b.isEmpty() || b.length() > 200 ? null : b;
            }
        }
        return null;
    }

    /**
     * Moves to the next part and returns its headers, or null after the closing boundary. The
     * previous part's body must have been read with {@link #copyBody}.
     */
    Part next() throws IOException {
        if (finished) {
            return null;
        }
        if (!skipToDelimiter()) {
            throw new MalformedException("the form data ended before its closing boundary");
        }
        fill(2);
        if (end - start < 2) {
            throw new MalformedException("the form data ended after a boundary");
        }
        if (buf[start] == '-' && buf[start + 1] == '-') {
            finished = true;
            return null;
        }
        // Optional whitespace after the boundary, then CRLF.
        String first = readLine();
        if (!first.isBlank()) {
            throw new MalformedException("unexpected text after a boundary");
        }
        Map<String, String> headers = new LinkedHashMap<>();
        int total = 0;
        for (String line = readLine(); !line.isEmpty(); line = readLine()) {
            total += line.length();
            if (total > MAX_HEADER_BYTES) {
                throw new MalformedException("a part's headers are longer than " + MAX_HEADER_BYTES + " bytes");
            }
            int colon = line.indexOf(':');
            if (colon > 0) {
                headers.put(line.substring(0, colon).trim().toLowerCase(Locale.ROOT), line.substring(colon + 1).trim());
            }
        }
        String disposition = headers.getOrDefault("content-disposition", "");
        return new Part(param(disposition, "name"), param(disposition, "filename"), headers);
    }

    /**
     * Copies the current part's body to {@code out}; stops after {@code limit} bytes and throws.
     *
     * @return the number of bytes copied
     */
    long copyBody(OutputStream out, long limit, String what) throws IOException {
        long n = 0;
        while (true) {
            int found = indexOf(delimiter, start, end);
            if (found >= 0) {
                n += write(out, found - start, limit, n, what);
                return n; // leave the delimiter for next()
            }
            // Keep a tail that may be the start of the delimiter.
            int safe = Math.max(start, end - (delimiter.length - 1));
            n += write(out, safe - start, limit, n, what);
            if (eof) {
                throw new MalformedException("the form data ended inside a part");
            }
            compact();
            readMore();
        }
    }

    private long write(OutputStream out, int len, long limit, long sofar, String what) throws IOException {
        if (sofar + len > limit) {
            throw new TooLargeException(what + " is over the upload limit of " + limit + " bytes");
        }
        out.write(buf, start, len);
        start += len;
        return len;
    }

    /** Too many bytes. */
    static final class TooLargeException extends IOException {
        private static final long serialVersionUID = 1L;

        TooLargeException(String message) {
            super(message);
        }
    }

    private boolean skipToDelimiter() throws IOException {
        while (true) {
            int found = indexOf(delimiter, start, end);
            if (found >= 0) {
                start = found + delimiter.length;
                return true;
            }
            if (eof) {
                return false;
            }
            start = Math.max(start, end - (delimiter.length - 1));
            compact();
            readMore();
        }
    }

    private String readLine() throws IOException {
        ByteArrayOutputStream line = new ByteArrayOutputStream();
        while (true) {
            if (start == end) {
                compact();
                readMore();
                if (start == end) {
                    throw new MalformedException("the form data ended inside a part's headers");
                }
            }
            byte b = buf[start++];
            if (b == '\n') {
                byte[] l = line.toByteArray();
                int len = l.length > 0 && l[l.length - 1] == '\r' ? l.length - 1 : l.length;
                return new String(l, 0, len, StandardCharsets.UTF_8);
            }
            line.write(b);
            if (line.size() > MAX_HEADER_BYTES) {
                throw new MalformedException("a header line is longer than " + MAX_HEADER_BYTES + " bytes");
            }
        }
    }

    private void fill(int wanted) throws IOException {
        while (end - start < wanted && !eof) {
            compact();
            readMore();
        }
    }

    private void compact() {
        if (start > 0) {
            System.arraycopy(buf, start, buf, 0, end - start);
            end -= start;
            start = 0;
        }
    }

    private void readMore() throws IOException {
        if (end == buf.length) {
            return;
        }
        int r = in.read(buf, end, buf.length - end);
        if (r < 0) {
            eof = true;
        } else {
            end += r;
        }
    }

    private int indexOf(byte[] pattern, int from, int to) {
        outer:
        for (int i = from; i <= to - pattern.length; i++) {
            for (int j = 0; j < pattern.length; j++) {
                if (buf[i + j] != pattern[j]) {
                    continue outer;
                }
            }
            return i;
        }
        return -1;
    }

    /** A parameter of a Content-Disposition header ({@code name="x"}), or null. */
    static String param(String header, String name) {
        int i = 0;
        String lower = header.toLowerCase(Locale.ROOT);
        while (i < header.length()) {
            int semi = header.indexOf(';', i);
            if (semi < 0) {
                return null;
            }
            int p = semi + 1;
            while (p < header.length() && header.charAt(p) == ' ') {
                p++;
            }
            if (lower.startsWith(name + "=", p)) {
                int v = p + name.length() + 1;
                if (v < header.length() && header.charAt(v) == '"') {
                    StringBuilder b = new StringBuilder();
                    for (int k = v + 1; k < header.length(); k++) {
                        char c = header.charAt(k);
                        // Browsers send backslashes as they are (old ones sent C:\dir\file): keep them,
                        // so the name check can refuse them.
                        if (c == '"') {
                            return b.toString();
                        } else {
                            b.append(c);
                        }
                    }
                    return b.toString();
                }
                int stop = header.indexOf(';', v);
                return header.substring(v, stop < 0 ? header.length() : stop).trim();
            }
            i = p;
        }
        return null;
    }
}
