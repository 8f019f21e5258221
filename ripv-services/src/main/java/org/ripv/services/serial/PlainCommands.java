package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.service.Reply;

/**
 * Plain vehicle commands on one link: the command is written with the line ending; the reply is
 * read until the prompt or the idle timeout, and returned without the echoed command line and
 * the prompt. {@code ?cancel} interrupts it ({@link CommandCancel}); a vehicle a cancel left away
 * from its prompt is resynchronised ({@link LineSync}) before the next command.
 */
final class PlainCommands {
    private final LinkSettings settings;
    private final VehicleText vehicleText;
    private final ReplyReader replies;
    private final VehicleConsole console;
    private final LinkState state;
    private final CommandCancel plainCancel;
    private final LineSync lineSync;
    /** A cancelled command left the vehicle away from its prompt: the next command resynchronises first. */
    private boolean lineDirty;

    PlainCommands(LinkSettings settings, VehicleText vehicleText, ReplyReader replies, VehicleConsole console, LinkState state) {
        this.settings = settings;
        this.vehicleText = vehicleText;
        this.replies = replies;
        this.console = console;
        this.state = state;
        this.plainCancel = new CommandCancel(settings.interrupt());
        this.lineSync = new LineSync(settings, replies);
    }

    /** From ?cancel (another thread): true when a command runs and the link has an interrupt. */
    boolean cancel() {
        return plainCancel.ask();
    }

    /** Writes one command line and returns the vehicle's answer (or the cancel's). */
    Reply run(Connection l, String command, String user) throws IOException, ServiceException {
        StringBuilder text = new StringBuilder();
        boolean closed;
        l.listen();
        plainCancel.begin();
        try {
            if (lineDirty) {
                lineDirty = !lineSync.resync(l);
            }
            plainCancel.send(l, (command + settings.lineEnding()).getBytes(StandardCharsets.ISO_8859_1));
            closed = replies.read(l, text, settings.commandTimeout().toMillis(), command, plainCancel);
        } finally {
            plainCancel.end();
            l.stopListening();
        }
        if (plainCancel.asked() && !closed) {
            return cancelled(l, command, user, text);
        }
        if (text.isEmpty() && !closed) {
            throw new ServiceException(ErrorCode.TIMEOUT, "no answer to '" + Header.abbreviate(command) + "' from " + l.describe()
                    + " within " + settings.idleTimeout().toMillis() + " ms");
        }
        String reply = vehicleText.clean(text.toString(), command);
        if (closed) {
            state.failed(l, new EOFException("closed by the vehicle"));
            return Reply.ok(reply + (reply.isEmpty() ? "" : "\n") + "(the vehicle closed the link)");
        }
        return Reply.ok(reply);
    }

    /**
     * A plain command was interrupted: the reply is an error (the server turns it into CANCELLED
     * naming who asked), saying whether the vehicle is back at its prompt and what it printed.
     */
    private Reply cancelled(Connection l, String command, String user, StringBuilder text) throws ServiceException {
        boolean back = vehicleText.endsWithPrompt(text);
        lineDirty = !back;
        String printed = vehicleText.clean(text.toString(), command);
        String how = "interrupted '" + Header.abbreviate(command) + "' with " + plainCancel.describe() + "; "
                + (back ? "the vehicle is back at its prompt"
                : "the vehicle was not back at its prompt within " + replies.settleMillis() / 1000 + " s (the next command"
                        + " waits for it)");
        console.transfer(user, how);
        throw new ServiceException(ErrorCode.CANCELLED, how + (printed.isEmpty() ? "" : "; it had printed:\n"
                + (printed.length() > 2000 ? "…" + printed.substring(printed.length() - 2000) : printed)));
    }
}
