package org.ripv.services.ingest;

import java.io.IOException;
import java.io.InputStream;
import net.jpountz.lz4.LZ4Exception;
import net.jpountz.lz4.LZ4Factory;
import net.jpountz.lz4.LZ4SafeDecompressor;
import org.ripv.slocum.SlocumFiles;

/**
 * The plain bytes of a compressed Slocum file ({@code .scd}, {@code .tcd}, {@code .dcd},
 * {@code .ecd}, …): a sequence of blocks, each a 2-byte big-endian length and that many bytes of
 * one LZ4 block, which decompress to the uncompressed format byte for byte. One block is in
 * memory at a time (at most {@value #MAX_BLOCK} bytes decompressed, as the glider writes them).
 */
public final class Lz4BlockInputStream extends InputStream {
    /** The largest block the glider's writers and the known decoders use. */
    public static final int MAX_BLOCK = 65_536;
    private static final LZ4SafeDecompressor LZ4 = LZ4Factory.fastestJavaInstance().safeDecompressor();

    private final InputStream in;
    private final String file;
    private final byte[] compressed = new byte[65_535];
    private final byte[] block = new byte[MAX_BLOCK];
    private int pos;
    private int end;
    private long compressedOffset;
    private long plainOffset;
    private final long maxPlainBytes;

    public Lz4BlockInputStream(InputStream in, String file) {
        this(in, file, IngestLimits.DEFAULT_MAX_PLAIN_BYTES);
    }

    /** As above, refusing to decompress more than {@code maxPlainBytes} (an LZ4 bomb: issue 33 item 8). */
    public Lz4BlockInputStream(InputStream in, String file, long maxPlainBytes) {
        this.in = in;
        this.file = file;
        this.maxPlainBytes = maxPlainBytes;
    }

    /** True for the compressed extensions: the middle letter of a three-letter Slocum extension is 'c'. */
    public static boolean isCompressedName(String name) {
        return SlocumFiles.isCompressedName(name);
    }

    @Override
    public int read() throws IOException {
        if (pos == end && !fill()) {
            return -1;
        }
        return block[pos++] & 0xff;
    }

    @Override
    public int read(byte[] b, int off, int len) throws IOException {
        if (len == 0) {
            return 0;
        }
        if (pos == end && !fill()) {
            return -1;
        }
        int n = Math.min(len, end - pos);
        System.arraycopy(block, pos, b, off, n);
        pos += n;
        return n;
    }

    private boolean fill() throws IOException {
        plainOffset += end;
        pos = 0;
        end = 0;
        int hi = in.read();
        if (hi < 0) {
            return false;
        }
        int lo = in.read();
        if (lo < 0) {
            throw corrupt("the file ends inside a block length");
        }
        int length = hi << 8 | lo;
        if (length == 0) {
            throw corrupt("a block of length 0");
        }
        int got = in.readNBytes(compressed, 0, length);
        if (got < length) {
            throw corrupt("the file ends inside an LZ4 block (" + got + " of " + length + " bytes)");
        }
        try {
            end = LZ4.decompress(compressed, 0, length, block, 0, MAX_BLOCK);
        } catch (LZ4Exception e) {
            throw corrupt("a corrupt LZ4 block of " + length + " bytes (" + e.getMessage() + ")");
        }
        if (plainOffset + end > maxPlainBytes) {
            throw new CompressedFormatException(new SlocumFormatException(file, compressedOffset, "the file decompresses to more"
                    + " than " + maxPlainBytes + " bytes, the most one file may (the DatabaseServer's --ingest-max-bytes)"));
        }
        compressedOffset += 2 + length;
        return end > 0 || fill();
    }

    private IOException corrupt(String reason) {
        return new CompressedFormatException(new SlocumFormatException(file, compressedOffset,
                reason + " (compressed byte offset; " + plainOffset + " bytes decompressed before it)"));
    }

    @Override
    public void close() throws IOException {
        in.close();
    }

    /** Carries a decoding failure of the compressed layer through the InputStream interface. */
    static final class CompressedFormatException extends IOException {
        private static final long serialVersionUID = 1L;

        CompressedFormatException(SlocumFormatException cause) {
            super(cause.getMessage(), cause);
        }

        SlocumFormatException format() {
            return (SlocumFormatException) getCause();
        }
    }
}
