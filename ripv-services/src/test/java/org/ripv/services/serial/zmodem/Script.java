package org.ripv.services.serial.zmodem;

import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import org.ripv.services.serial.ymodem.ByteLink;

/** A scripted ZMODEM peer: frames built with our writer, played back in uneven chunks; what the other side writes is dropped. */
final class Script {
    /** The script ran out: the call dropped. */
    static final class Exhausted extends EOFException {
        private static final long serialVersionUID = 1L;

        Exhausted() {
            super("the call dropped (end of the script)");
        }
    }

    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    private final ZFrameWriter w = new ZFrameWriter(new ByteLink() {
        @Override
        public int read(byte[] b, int o, int l, long t) {
            return 0;
        }

        @Override
        public void write(byte[] b, int o, int l) {
            bytes.write(b, o, l);
        }
    });

    Script hex(int type, long pos) throws IOException {
        w.hex(ZHeader.position(type, pos));
        return this;
    }

    Script bin32(int type, long pos) throws IOException {
        w.binary(ZHeader.position(type, pos).as32(true));
        return this;
    }

    Script zfile(String name, long size, long mtime) throws IOException {
        w.binary(ZHeader.flags(Zmodem.ZFILE, 1, 0, 0, 0).as32(true));
        byte[] info = (name + "\0" + size + " " + Long.toOctalString(mtime) + " 100644 0 1 " + size + "\0")
                .getBytes(StandardCharsets.ISO_8859_1);
        w.data(info, 0, info.length, Zmodem.ZCRCW, true);
        return this;
    }

    Script data(byte[] d, int end) throws IOException {
        w.data(d, 0, d.length, end, true);
        return this;
    }

    Script raw(byte[] b) {
        bytes.write(b, 0, b.length);
        return this;
    }

    byte[] bytes() {
        return bytes.toByteArray();
    }

    /** Plays {@code script} back, then reports the link closed. */
    static ByteLink playing(byte[] script) {
        return new ByteLink() {
            private int at;

            @Override
            public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
                if (at >= script.length) {
                    throw new Exhausted();
                }
                int n = Math.min(len, Math.min(script.length - at, 1 + (at % 251)));
                System.arraycopy(script, at, buffer, offset, n);
                at += n;
                return n;
            }

            @Override
            public void write(byte[] buffer, int offset, int len) {
            }
        };
    }
}
