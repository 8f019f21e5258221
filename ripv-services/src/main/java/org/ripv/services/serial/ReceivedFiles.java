package org.ripv.services.serial;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ErrorCode;
import org.ripv.rmi.RmiSupport;

/**
 * Files a vehicle sent go to the server whole, in the command's one reply, so they are read into
 * the service's memory: their sizes are checked first, and a batch that would take more than a
 * quarter of the heap is refused with a message saying so, instead of ending the service (and
 * every other vehicle's link with it) in an OutOfMemoryError — or, on a large heap, sending a
 * reply RMI cannot carry: a 1.5 GB {@code zmodem:get} on an 8 GB heap was read whole and its one
 * reply dropped by the server's filter, so the user never got an answer (issue 33 item 9). The
 * budget is therefore also at most half of {@link RmiSupport#MAX_RMI_BYTES}.
 */
final class ReceivedFiles {
    private ReceivedFiles() {
    }

    /** A quarter of the heap this service may grow to, and at most half of what one RMI reply may carry. */
    static long budget() {
        return budget(Runtime.getRuntime().maxMemory());
    }

    static long budget(long maxHeap) {
        return Math.min(maxHeap / 4, RmiSupport.MAX_RMI_BYTES / 2);
    }

    /** Throws TRANSFER_FAILED when {@code files} hold more than {@code budget} bytes together. */
    static void checkFits(String verb, List<Path> files, long budget) throws IOException, ServiceException {
        long total = 0;
        for (Path f : files) {
            total += Files.size(f);
        }
        if (total > budget) {
            throw new ServiceException(ErrorCode.TRANSFER_FAILED, verb + ": the vehicle sent " + total + " bytes in "
                    + files.size() + " file(s), more than this SerialPortServer hands on in one reply (" + budget
                    + " bytes: a quarter of its heap, and at most half of what one reply to the server may carry);"
                    + " nothing was stored. Fetch fewer files at a time; a single file this large cannot come through"
                    + " RIPV in one piece: take it off the vehicle another way, or split it on the vehicle");
        }
    }
}
