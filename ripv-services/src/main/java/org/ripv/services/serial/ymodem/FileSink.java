package org.ripv.services.serial.ymodem;

import java.io.IOException;
import java.io.OutputStream;

/**
 * Where a {@link YmodemReceiver} puts files. A file is written to {@link #begin}'s stream and
 * only becomes visible with {@link #complete}; {@link #discard} throws away a failed one, so an
 * aborted transfer never leaves a file that looks complete.
 */
public interface FileSink {
    OutputStream begin(FileHeader file) throws IOException;

    void complete(FileHeader file) throws IOException;

    void discard(FileHeader file);
}
