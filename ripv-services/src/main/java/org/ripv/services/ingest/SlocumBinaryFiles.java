package org.ripv.services.ingest;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import org.ripv.slocum.SlocumFiles;

/** Binary files on their way into {@link DbaIngest}: recognised by content or name, decoded cycle by cycle. */
public final class SlocumBinaryFiles {
    private SlocumBinaryFiles() {}

    /** True for a plain binary file (its first line is the binary label) or a compressed one by its name. */
    public static boolean isBinary(String name, byte[] data) {
        return SlocumFiles.isCompressedName(name) || data.length >= 64 && SlocumFiles.hasBinaryLabel(data)
                || SlocumFiles.isBinaryName(name);
    }

    /**
     * A binary file's cycles for {@link DbaIngest}, decoded as they are read (one cycle in memory).
     *
     * @throws MissingSensorListException when its sensor list is in a cache file the cache lacks
     * @throws SlocumFormatException      when its header cannot be decoded
     */
    public static Cycles cycles(String name, byte[] data, SensorListCache cache) throws IOException, SlocumFormatException {
        return cycles(name, data, cache, IngestLimits.DEFAULT_MAX_PLAIN_BYTES);
    }

    /** As above, decompressing at most {@code maxPlainBytes}. */
    public static Cycles cycles(String name, byte[] data, SensorListCache cache, long maxPlainBytes)
            throws IOException, SlocumFormatException {
        if (data.length == 0) {
            throw new SlocumFormatException(name, 0, "the file is empty (0 bytes)");
        }
        SlocumBinaryReader r = SlocumBinaryReader.open(new ByteArrayInputStream(data), name, cache, maxPlainBytes);
        return new BinaryCycles(r, name);
    }

    /**
     * The DBA text of a binary file, as {@code ripv slocum decode} prints it (the ingest reads
     * {@link #cycles} instead, without this text).
     *
     * @throws MissingSensorListException when its sensor list is in a cache file the cache lacks
     * @throws SlocumFormatException      when it cannot be decoded; nothing is returned
     */
    public static byte[] dba(String name, byte[] data, SensorListCache cache) throws IOException, SlocumFormatException {
        if (data.length == 0) {
            throw new SlocumFormatException(name, 0, "the file is empty (0 bytes)");
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream(data.length * 4);
        try (SlocumBinaryReader r = SlocumBinaryReader.open(new ByteArrayInputStream(data), name, cache);
             Writer w = new OutputStreamWriter(out, StandardCharsets.US_ASCII)) {
            DbaText text = DbaText.start(w, r.tags(), r.sensors());
            double[] row = new double[r.sensors().size()];
            while (r.next(row)) {
                text.row(row);
            }
        }
        return out.toByteArray();
    }
}
