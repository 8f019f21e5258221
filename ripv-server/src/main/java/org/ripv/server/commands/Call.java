package org.ripv.server.commands;

import org.ripv.messages.ErrorCode;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Result;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.requests.ServerReplies;

/**
 * One run of a server command: the request, the command it names, the line's words (word 0 is
 * the command; a vehicle name already replaced by its MailBox's address) and, for a gated
 * command, the user as the permit file knows them; for a command with options, the line parsed
 * into its options object ({@link ServerCommand#options}).
 */
public record Call(IncomingServerMessage request, ServerCommand command, String[] words, PermitFile.User user, Object options) {
    /** A call of a command without options. */
    public Call(IncomingServerMessage request, ServerCommand command, String[] words, PermitFile.User user) {
        this(request, command, words, user, null);
    }

    /** The line as the command's options class read it. */
    public <T> T options(Class<T> type) {
        return type.cast(options);
    }

    /** Who sent it. */
    public String userName() {
        return request.header().origin().user();
    }

    public String clientId() {
        return request.header().origin().clientId();
    }

    /** Word {@code i}, or the command's usage as the error. */
    public String arg(int i) {
        if (words.length <= i) {
            throw new IllegalArgumentException("usage: " + command.usage());
        }
        return words[i];
    }

    /** Exactly {@code n} words, or the command's usage as the error. */
    public void expectWords(int n) {
        if (words.length != n) {
            throw new IllegalArgumentException("usage: " + command.usage());
        }
    }

    /** A whole number the line gives, or an error that quotes it. */
    public static long number(String s, String what) {
        try {
            return Long.parseLong(s);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + " must be a whole number, got '" + s + "'");
        }
    }

    public OutgoingServerMessage ok(String text, Result result) {
        return ServerReplies.ok(request, command.fid(), text, result);
    }

    public OutgoingServerMessage error(ErrorCode code, String text) {
        return ServerReplies.error(request, command.fid(), code, text);
    }
}
