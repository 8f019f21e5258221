package org.ripv.services.ingest;

/**
 * How much one file may put into the database (issue 33 item 8): a 100 KB LZ4 {@code .scd} from a
 * hostile vehicle decompressed to 12.6 million cycles, written in one transaction while the
 * DatabaseServer's MailBox stayed busy for minutes. A file over either limit is refused, nothing of
 * it stored, with the limit and the option that raises it. The operator sets them with the
 * DatabaseServer's {@code --ingest-max-bytes} and {@code --ingest-max-rows}.
 *
 * @param maxPlainBytes bytes a compressed file may decompress to
 * @param maxRows       cycles (rows) one file may hold
 */
public record IngestLimits(long maxPlainBytes, long maxRows) {
    /** Far above a real glider file (a day's full-resolution .dbd is a few MB), far below a bomb. */
    public static final long DEFAULT_MAX_PLAIN_BYTES = 256L << 20;
    /** A day of 1 s cycles is 86,400 rows. */
    public static final long DEFAULT_MAX_ROWS = 1_000_000;
    /** Rows between two looks at a cancel request. */
    public static final int CANCEL_EVERY = 1024;

    public IngestLimits {
        if (maxPlainBytes < 1) {
            throw new IllegalArgumentException("--ingest-max-bytes must be positive, got " + maxPlainBytes);
        }
        if (maxRows < 1) {
            throw new IllegalArgumentException("--ingest-max-rows must be positive, got " + maxRows);
        }
    }

    public static IngestLimits defaults() {
        return new IngestLimits(DEFAULT_MAX_PLAIN_BYTES, DEFAULT_MAX_ROWS);
    }

    /** The refusal of a file with more rows than {@link #maxRows}. */
    public String tooManyRows(String file) {
        return file + " holds more than " + maxRows + " rows, the most one file may (the DatabaseServer's --ingest-max-rows)";
    }
}
