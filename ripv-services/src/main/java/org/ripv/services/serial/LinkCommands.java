package org.ripv.services.serial;

import java.io.IOException;
import java.util.Optional;
import org.ripv.commands.WordTable;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ErrorCode;
import org.ripv.service.Reply;
import org.ripv.service.Request;

/**
 * A link's own commands, by word (thesis: SerialPortHandler's command switch): each named once
 * with its usage and help, what is checked before the link is locked, and what runs on it.
 * Anything else is a plain command for the vehicle — except a word of a transfer's family
 * ({@code ymodem:}, {@code zmodem:}) or a {@code ?} word, which is refused with the usages the
 * table holds for it.
 */
final class LinkCommands {
    /** Word families that never reach the vehicle: a word of theirs not in the table is refused. */
    private static final String[] FAMILIES = {"ymodem:", "zmodem:"};

    /** What runs a command on the link. */
    @FunctionalInterface
    interface Run {
        Reply run(Connection link, Request request) throws IOException, ServiceException;
    }

    /**
     * Checks a command before the link is locked, so that a refused one never touches it.
     * Returns what the console records for it (null: the command as sent).
     */
    @FunctionalInterface
    interface Check {
        String check(Request request) throws ServiceException;
    }

    /** One link command. */
    record Command(String word, String usage, String help, Check before, Run run) implements WordTable.Word {
        Command(String word, String usage, String help, Run run) {
            this(word, usage, help, r -> null, run);
        }
    }

    private final WordTable<Command> table = WordTable.exact();

    LinkCommands(YmodemCommands ymodem, ZmodemCommands zmodem, ToVehicleCommands toVehicle, KeyCommands keys) {
        table.add(new Command("ymodem:get", "ymodem:get NAME…", "fetch files from the vehicle by YMODEM", ymodem::get))
                .add(new Command("ymodem:put", "ymodem:put NAME", "send an uploaded file to the vehicle by YMODEM", ymodem::put))
                .add(new Command("zmodem:get", "zmodem:get NAME…", "fetch files from the vehicle by ZMODEM (lrzsz)", zmodem::get))
                .add(new Command("zmodem:put", "zmodem:put NAME", "send an uploaded file to the vehicle by ZMODEM", zmodem::put))
                .add(new Command(ToVehicleCommands.WORD, ToVehicleCommands.WORD + " to-vehicle/FOLDER/NAME",
                        "send a file of the server's to-vehicle folder", r -> {
                            toVehicle.requireOn(); // a link that does not send to-vehicle files never starts one
                            return null;
                        }, toVehicle::put))
                .add(new Command(KeyCommands.WORD, KeyCommands.WORD + " KEY", "press one control key the link allows",
                        // a key the link does not allow is refused before the lock: nothing reaches the vehicle
                        r -> KeyCommands.WORD + " " + keys.allowed(r.arguments()).name(),
                        (l, r) -> keys.press(l, keys.allowed(r.arguments()))));
    }

    /**
     * The link command a command line names; empty for a plain command.
     *
     * @throws ServiceException UNKNOWN_COMMAND for a word of a family, or a {@code ?} word, the table does not hold
     */
    Optional<Command> find(String command) throws ServiceException {
        String word = WordTable.firstWord(command);
        Optional<Command> c = table.find(word);
        if (c.isPresent()) {
            return c;
        }
        for (String family : FAMILIES) {
            if (word.startsWith(family)) {
                throw new ServiceException(ErrorCode.UNKNOWN_COMMAND, "unknown '" + word + "'; use " + table.usages(family));
            }
        }
        if (word.startsWith("?")) {
            throw new ServiceException(ErrorCode.UNKNOWN_COMMAND, "'" + word
                    + "' is not a vehicle command; the only ? command a link takes is " + table.usages("?"));
        }
        return Optional.empty();
    }
}
