package org.ripv.services.serial;

import java.io.IOException;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ErrorCode;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.ripv.services.serial.ymodem.FileNames;
import org.ripv.services.serial.ymodem.SendFile;

/**
 * {@code tovehicle:put to-vehicle/FOLDER/NAME}: the server, on a call, hands over one file of the
 * MailBox's {@code to-vehicle/} folder. It goes out by the link's {@code to-vehicle=} protocol
 * under its plain NAME, and counts as sent only when the vehicle's own {@code dir} then lists NAME
 * with the same size: a transfer the vehicle did not keep whole must stay for the next call.
 */
record ToVehicleCommands(PilotSettings pilot, ZmodemCommands zmodem, YmodemCommands ymodem, PlainCommands plain) {
    static final String WORD = "tovehicle:put";
    /** The vehicle's listing command (PicoDOS and GliderDOS alike). */
    static final String LIST_COMMAND = "dir";
    /** A {@code dir} line: name, size, then date and time. */
    private static final Pattern DIR_LINE = Pattern.compile("^\\s*([^\\s/\\\\]+)\\s+(\\d{1,18})\\s+\\S+\\s+\\S+\\s*$");

    /** Whether the link sends its to-vehicle folder; checked before the link is touched. */
    void requireOn() throws ServiceException {
        if (pilot.toVehicle() == ToVehicleMode.OFF) {
            throw new ServiceException(ErrorCode.NOT_AVAILABLE, "this link does not send to-vehicle files; give its --link"
                    + " to-vehicle=zmodem or to-vehicle=ymodem to have them sent on each call");
        }
    }

    Reply put(Connection c, Request request) throws IOException, ServiceException {
        requireOn();
        List<String> args = request.arguments();
        if (args.size() != 1) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, WORD + " takes one to-vehicle/FOLDER/NAME; got " + args.size());
        }
        var attachment = request.attachment().orElseThrow(() -> new ServiceException(ErrorCode.BAD_REQUEST,
                "no file came with " + WORD + " " + args.get(0) + " (the server attaches it from its to-vehicle folder)"));
        String path = args.get(0);
        String name;
        try {
            name = FileNames.requirePlain(path.substring(path.lastIndexOf('/') + 1));
        } catch (IllegalArgumentException e) {
            throw new ServiceException(ErrorCode.BAD_FILE_NAME, e.getMessage());
        }
        SendFile file = SendFile.of(name, attachment.data());
        Reply sent = pilot.toVehicle() == ToVehicleMode.ZMODEM ? zmodem.put(c, request, file) : ymodem.put(c, request, file);
        Reply listing = plain.run(c, LIST_COMMAND, request.user());
        Long size = sizeOf(listing.text(), name);
        if (size == null) {
            throw new ServiceException(ErrorCode.TRANSFER_FAILED, sent.text() + "; but the vehicle's " + LIST_COMMAND
                    + " does not list " + name + ", so it stays for the next call");
        }
        if (size != file.length()) {
            throw new ServiceException(ErrorCode.TRANSFER_FAILED, sent.text() + "; but the vehicle's " + LIST_COMMAND
                    + " shows " + name + " with " + size + " bytes, not " + file.length() + ", so it stays for the next call");
        }
        return Reply.ok(sent.text() + " by " + pilot.toVehicle().name() + "; the vehicle's " + LIST_COMMAND + " lists "
                + name + " with " + size + " bytes");
    }

    /** The size a {@code dir} listing gives a file (names compared without case, as PicoDOS does), or null. */
    static Long sizeOf(String listing, String name) {
        for (String line : listing.split("\r?\n")) {
            Matcher m = DIR_LINE.matcher(line);
            if (m.matches() && m.group(1).equalsIgnoreCase(name)) {
                return Long.parseLong(m.group(2));
            }
        }
        return null;
    }
}
