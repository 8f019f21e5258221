package org.ripv.services.ingest;

import java.io.ByteArrayOutputStream;
import net.jpountz.lz4.LZ4Compressor;
import net.jpountz.lz4.LZ4Factory;

/** Writes the compressed Slocum form ({@link Lz4BlockInputStream}) of a plain file: for tests, benchmarks and tools. */
public final class Lz4Blocks {
    private static final LZ4Compressor LZ4 = LZ4Factory.fastestJavaInstance().fastCompressor();

    private Lz4Blocks() {}

    /** The plain bytes in blocks of at most {@code blockSize} bytes, each a 2-byte big-endian length and an LZ4 block. */
    public static byte[] compress(byte[] plain, int blockSize) {
        if (blockSize < 1 || blockSize > 60_000) {
            throw new IllegalArgumentException("a block of " + blockSize + " bytes: use 1 to 60000 (its LZ4 form must fit a 2-byte length)");
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream(plain.length / 2 + 64);
        byte[] block = new byte[LZ4.maxCompressedLength(blockSize)];
        for (int at = 0; at < plain.length; at += blockSize) {
            int n = LZ4.compress(plain, at, Math.min(blockSize, plain.length - at), block, 0, block.length);
            out.write(n >> 8);
            out.write(n);
            out.write(block, 0, n);
        }
        return out.toByteArray();
    }
}
