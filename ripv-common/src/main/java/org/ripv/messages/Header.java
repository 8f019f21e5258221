package org.ripv.messages;

import java.io.Serializable;
import java.util.List;
import java.util.Objects;
import org.ripv.commands.SingleLineCommand;

/**
 * The addressing half of a {@link Message}: who sent it, where it goes and what it asks.
 *
 * @param messageId          chosen by the client; replies carry it back so they can be matched
 * @param origin             the client and user it came from (the server sets the user and roles;
 *                           what a client claims there is never trusted)
 * @param roles              the user's roles from the permit file, set by the server
 * @param serviceDestination the full service name ({@code <DatabaseServer>::<host>}), or empty
 *                           for a server command
 * @param mailboxAddress     the MailBox that runs the command; empty for a server command
 * @param body               the command itself ({@code dir}, {@code SELECT ...}, {@code ?services})
 * @param priority           which inbox of the MailBox it waits in
 * @param attachment         an optional file travelling with the command, or null
 */
public record Header(long messageId, IdBadge origin, List<String> roles, String serviceDestination,
                     String mailboxAddress, String body, Priority priority, Attachment attachment)
        implements Serializable {

    public Header {
        Objects.requireNonNull(origin, "origin");
        roles = roles == null ? List.of() : List.copyOf(roles);
        serviceDestination = serviceDestination == null ? "" : serviceDestination;
        mailboxAddress = mailboxAddress == null ? "" : mailboxAddress;
        body = body == null ? "" : body;
        priority = priority == null ? Priority.NORMAL : priority;
    }

    /** A request from a client: the server fills in user, roles and destination. */
    public static Header request(long messageId, String mailboxAddress, String body, Priority priority) {
        return new Header(messageId, new IdBadge("000000", ""), List.of(), "", mailboxAddress, body,
                priority, null);
    }

    /** True when the body is a command for the server itself ({@code ?...}). */
    public boolean isServerCommand() {
        return body.startsWith("?");
    }

    /** The request's name while it waits for its reply: its sender's client id and its message id ({@code 123456#7}). */
    public String requestKey() {
        return origin.clientId() + "#" + messageId;
    }

    public Header withOrigin(IdBadge newOrigin, List<String> newRoles) {
        return new Header(messageId, newOrigin, newRoles, serviceDestination, mailboxAddress, body,
                priority, attachment);
    }

    public Header withDestination(String service) {
        return new Header(messageId, origin, roles, service, mailboxAddress, body, priority, attachment);
    }

    public Header withAttachment(Attachment file) {
        return new Header(messageId, origin, roles, serviceDestination, mailboxAddress, body, priority, file);
    }

    @Override
    public String toString() {
        return "Header[#" + messageId + " from " + origin.clientId() + "/" + origin.user()
                + " to '" + mailboxAddress + "' " + priority + " '" + abbreviate(body) + "'"
                + (attachment == null ? "" : " +" + attachment) + "]";
    }

    /**
     * The first 80 characters of a text, for logs and error messages, with control characters
     * made visible ({@code \r}, {@code ^C}) so that no value can forge a log line.
     */
    public static String abbreviate(String s) {
        return SingleLineCommand.shown(s);
    }
}
