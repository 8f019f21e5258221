package org.ripv.server.notify;

import java.io.IOException;
import java.util.List;
import java.util.Locale;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.NotifyList;
import org.ripv.messages.OutgoingServerMessage;

/**
 * {@code ?notify add webhook URL EVENTS [MAILBOX-GLOB]}, {@code ?notify add email ADDRESS EVENTS
 * [MAILBOX-GLOB]}, {@code ?notify list}, {@code ?notify remove ID}: each user manages their own
 * subscriptions.
 */
public final class NotifyCommands {
    static final String USAGE = "?notify add webhook URL EVENTS [MAILBOX-GLOB] | ?notify add email ADDRESS EVENTS [MAILBOX-GLOB]"
            + " | ?notify list | ?notify remove ID   (EVENTS: a comma list such as SURFACED,DIVED, or all)";

    private final Notifier notifier;
    private final String via;

    public NotifyCommands(Notifier notifier, String via) {
        this.notifier = notifier;
        this.via = via;
    }

    public OutgoingServerMessage run(IncomingServerMessage request, String fid, String[] w) throws IOException {
        String user = request.header().origin().user();
        String sub = w.length > 1 ? w[1].toLowerCase(Locale.ROOT) : "";
        try {
            switch (sub) {
                case "add" -> {
                    if (w.length < 5 || w.length > 6) {
                        return error(request, fid, "usage: " + USAGE);
                    }
                    Subscription.Channel channel = switch (w[2].toLowerCase(Locale.ROOT)) {
                        case "webhook" -> Subscription.Channel.WEBHOOK;
                        case "email", "e-mail", "mail" -> Subscription.Channel.EMAIL;
                        default -> throw new IllegalArgumentException("'" + w[2] + "' is not webhook or email");
                    };
                    Subscription s = notifier.add(user, channel, w[3], w[4], w.length == 6 ? w[5] : "*");
                    return ok(request, fid, "subscription " + s.id + ": " + s.eventsText() + " of " + s.glob + " to "
                            + channel.name().toLowerCase(Locale.ROOT) + " " + s.target, new NotifyList(List.of(s.view())));
                }
                case "list" -> {
                    List<Subscription> mine = notifier.of(user);
                    StringBuilder b = new StringBuilder(mine.size() + " subscription(s)");
                    for (Subscription s : mine) {
                        b.append('\n').append(s.id).append("  ").append(s.channel.name().toLowerCase(Locale.ROOT)).append(' ')
                                .append(s.target).append("  ").append(s.eventsText()).append("  ").append(s.glob)
                                .append("  last: ").append(s.lastResult());
                    }
                    return ok(request, fid, b.toString(), new NotifyList(mine.stream().map(Subscription::view).toList()));
                }
                case "remove" -> {
                    if (w.length != 3) {
                        return error(request, fid, "usage: ?notify remove ID");
                    }
                    if (!notifier.remove(user, w[2])) {
                        return error(request, fid, "you have no subscription " + w[2] + "; ?notify list shows yours");
                    }
                    return ok(request, fid, "removed subscription " + w[2], null);
                }
                default -> {
                    return error(request, fid, "usage: " + USAGE);
                }
            }
        } catch (Notifier.Refused e) {
            return request.reply(Footer.error(fid, ErrorCode.FORBIDDEN, e.getMessage()).via(via));
        } catch (IllegalArgumentException e) {
            return error(request, fid, e.getMessage());
        }
    }

    private OutgoingServerMessage ok(IncomingServerMessage request, String fid, String text, NotifyList r) {
        return request.reply(Footer.ok(fid, text, r).via(via));
    }

    private OutgoingServerMessage error(IncomingServerMessage request, String fid, String text) {
        return request.reply(Footer.error(fid, ErrorCode.BAD_REQUEST, text).via(via));
    }
}
