package org.ripv.services.serial;

import java.io.IOException;
import java.util.List;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ErrorCode;
import org.ripv.service.Reply;

/**
 * {@code ?key KEY} on one link: one control key written to the vehicle, and what it printed in
 * answer (up to its prompt, or until it is quiet). The server sends {@code ?key MAILBOX KEY} here
 * as this command after checking the user's right to {@code ?key KEY} and the MailBox's lock;
 * here the link's own list ({@code keys=}) decides, and the console records who pressed what.
 */
record KeyCommands(String handle, PilotSettings pilot, LinkSettings settings, ReplyReader replies) {
    /** The command word the server forwards ({@code ?key ctrl-c}). */
    static final String WORD = "?key";

    /** The key a {@code ?key KEY} command names, if the link allows it; a clear refusal otherwise. */
    ControlKey allowed(List<String> arguments) throws ServiceException {
        if (arguments.size() != 1) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, "?key takes one key name, e.g. ?key ctrl-c; this link allows "
                    + ControlKey.describe(pilot.keys()));
        }
        ControlKey key;
        try {
            key = ControlKey.parse(arguments.get(0));
        } catch (IllegalArgumentException e) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, e.getMessage());
        }
        if (!pilot.allows(key)) {
            throw new ServiceException(ErrorCode.FORBIDDEN, "key '" + arguments.get(0) + "' is not allowed on " + handle
                    + "; it allows " + ControlKey.describe(pilot.keys()) + " (keys= in its --link)");
        }
        return key;
    }

    /** Writes the key and returns what the vehicle answered, its prompt included: that is what a pilot waits for. */
    Reply press(Connection c, ControlKey key) throws IOException {
        StringBuilder text = new StringBuilder();
        c.listen();
        boolean closed;
        try {
            c.write(new byte[] {key.code()}, 0, 1);
            c.flush();
            closed = replies.read(c, text, settings.commandTimeout().toMillis(), null);
        } finally {
            c.stopListening();
        }
        String answer = text.toString().replace("\r\n", "\n").replace('\r', '\n').strip();
        return Reply.ok("sent " + key.name() + (answer.isEmpty() ? "; the vehicle printed nothing within "
                + settings.idleTimeout().toMillis() + " ms" : "; the vehicle answered:\n" + answer)
                + (closed ? "\n(the vehicle closed the link)" : ""));
    }
}
