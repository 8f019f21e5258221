package org.ripv.services.serial;

import java.util.List;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ErrorCode;
import org.ripv.service.Request;
import org.ripv.services.serial.ymodem.FileNames;
import org.ripv.services.serial.ymodem.SendFile;

/** The one file a {@code ymodem:put} or {@code zmodem:put} sends: named once, plain, and attached by the server. */
final class PutFile {
    private PutFile() {}

    static SendFile of(Request request, String command) throws ServiceException {
        List<String> args = request.arguments();
        if (args.size() != 1) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, command + " takes one file name from the server's upload"
                    + " directory, e.g. " + command + " glider.bin; got " + args.size());
        }
        var attachment = request.attachment().orElseThrow(() -> new ServiceException(ErrorCode.BAD_REQUEST,
                "no file '" + args.get(0) + "' came with " + command + "; upload it to the server first (put FILE)"));
        try {
            return SendFile.of(FileNames.requirePlain(args.get(0)), attachment.data());
        } catch (IllegalArgumentException e) {
            throw new ServiceException(ErrorCode.BAD_FILE_NAME, e.getMessage());
        }
    }
}
