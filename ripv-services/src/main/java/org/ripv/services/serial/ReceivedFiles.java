package org.ripv.services.serial;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ErrorCode;

/**
 * Files a vehicle sent go to the server whole, in the command's one reply, so they are read into
 * the service's memory: their sizes are checked first, and a batch that would take more than a
 * quarter of the heap is refused with a message saying so, instead of ending the service (and
 * every other vehicle's link with it) in an OutOfMemoryError.
 */
final class ReceivedFiles {
    private ReceivedFiles() {
    }

    /** A quarter of the heap this service may grow to. */
    static long budget() {
        return Runtime.getRuntime().maxMemory() / 4;
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
                    + " bytes, a quarter of its heap); fetch fewer files at a time, or start the service with a larger"
                    + " heap (JAVA_TOOL_OPTIONS=-Xmx…)");
        }
    }
}
