package org.ripv.service;

import java.util.List;
import java.util.Optional;
import org.ripv.messages.Attachment;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;
import org.ripv.post.MailBox;

/** One command as a handler sees it, with a way to report progress on long work. */
public final class Request {
    private final IncomingServiceMessage message;
    private final MailBox<IncomingServiceMessage, OutgoingServiceMessage> box;
    private final String sid;
    private final String hop;

    Request(IncomingServiceMessage message, MailBox<IncomingServiceMessage, OutgoingServiceMessage> box,
            String sid, String hop) {
        this.message = message;
        this.box = box;
        this.sid = sid;
        this.hop = hop;
    }

    /** The command line, e.g. {@code dir} or {@code SELECT * FROM mission}. */
    public String command() {
        return message.header().body();
    }

    /** The command's words after the first, split on white space. */
    public List<String> arguments() {
        String[] words = command().trim().split("\\s+");
        return words.length <= 1 ? List.of() : List.of(words).subList(1, words.length);
    }

    /** The user the server logged in, never what a client claimed. */
    public String user() {
        return message.header().origin().user();
    }

    /** The user's roles from the server's permit file. */
    public List<String> roles() {
        return message.header().roles();
    }

    public Priority priority() {
        return message.header().priority();
    }

    /** The address of the MailBox running the command. */
    public String mailbox() {
        return box.address();
    }

    /** The file the server attached from its upload directory, if any. */
    public Optional<Attachment> attachment() {
        return Optional.ofNullable(message.header().attachment());
    }

    public IncomingServiceMessage message() {
        return message;
    }

    /** Sends a PROGRESS reply now; the final reply still comes from the handler's return. */
    public void progress(String text, Progress progress) {
        box.post(message.reply(Footer.progress(sid, text, progress).via(hop)));
    }
}
