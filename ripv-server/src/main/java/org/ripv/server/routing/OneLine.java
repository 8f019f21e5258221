package org.ripv.server.routing;

import org.ripv.commands.SingleLineCommand;
import org.ripv.messages.ErrorCode;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Step 3: the command is one line, not empty. Before any permit rule: a second line or a ^C
 * inside a command is never the user's to send.
 */
final class OneLine implements AdmissionStep {
    private static final Logger log = LoggerFactory.getLogger(OneLine.class);

    @Override
    public Verdict check(Admitting a) {
        if (a.body().isBlank()) {
            return Verdict.refuse(a.refuse(ErrorCode.BAD_REQUEST, "an empty command"));
        }
        try {
            SingleLineCommand.check(a.body(), SingleLineCommand.SERVER_MAX);
        } catch (IllegalArgumentException e) {
            log.info("refused a command from {} to {}: {}", a.userName(), a.address(), e.getMessage());
            return Verdict.refuse(a.refuse(ErrorCode.BAD_REQUEST, e.getMessage()));
        }
        return Verdict.PASS;
    }
}
