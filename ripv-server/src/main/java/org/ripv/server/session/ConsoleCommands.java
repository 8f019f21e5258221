package org.ripv.server.session;

import java.io.IOException;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Function;
import java.util.function.Supplier;
import org.ripv.commands.OptionValues;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.SessionState;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.permit.PermitFile;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * The server commands of the live console: {@code ?watch MAILBOX}, {@code ?unwatch MAILBOX},
 * {@code ?history MAILBOX [--last N] [--since ISO-TIME]} (its words read by picocli, {@link History}). Each returns its reply, or null when
 * it sent it itself ({@code ?watch}, whose reply must precede the first push).
 */
public final class ConsoleCommands {
    private final ConsoleHub hub;
    private final Supplier<PermitFile> permits;
    private final Function<String, Optional<Outlet>> outlets;
    private final String via;

    public ConsoleCommands(ConsoleHub hub, Supplier<PermitFile> permits, Function<String, Optional<Outlet>> outlets,
                           String via) {
        this.hub = hub;
        this.permits = permits;
        this.outlets = outlets;
        this.via = via;
    }

    /** Runs {@code ?watch} or {@code ?unwatch}; {@code w} is the command line split on white space. */
    public OutgoingServerMessage run(IncomingServerMessage request, String fid, String[] w) throws IOException {
        String user = request.header().origin().user();
        String clientId = request.header().origin().clientId();
        String word = w[0].toLowerCase(Locale.ROOT);
        if (w.length < 2) {
            return error(request, fid, ErrorCode.BAD_REQUEST, "usage: " + usage(word));
        }
        String mailbox;
        try {
            mailbox = MailboxAddress.parse(w[1]).toString();
        } catch (IllegalArgumentException e) {
            return error(request, fid, ErrorCode.UNKNOWN_MAILBOX, e.getMessage());
        }
        switch (word) {
            case "?watch" -> {
                if (w.length != 2) {
                    return error(request, fid, ErrorCode.BAD_REQUEST, "usage: " + usage(word));
                }
                String why = Rights.whyNotRead(permits.get(), user, mailbox);
                if (why != null) {
                    return error(request, fid, ErrorCode.FORBIDDEN, why);
                }
                Optional<Outlet> outlet = outlets.apply(clientId);
                if (outlet.isEmpty()) {
                    return null; // the client has gone
                }
                String refused = hub.watch(clientId, user, mailbox, outlet.get(), (state, recent) -> request.reply(
                        Footer.ok(fid, "watching " + mailbox + describe(state), new ConsoleBatch(mailbox, recent, 0, false))
                                .via(via)));
                return refused == null ? null : error(request, fid, ErrorCode.BAD_REQUEST, refused);
            }
            case "?unwatch" -> {
                boolean was = hub.unwatch(clientId, mailbox);
                return request.reply(Footer.ok(fid, was ? "stopped watching " + mailbox : "was not watching " + mailbox, null)
                        .via(via));
            }
            default -> throw new IllegalArgumentException("not a console command: " + w[0]);
        }
    }

    /** The words of {@code ?history}, read by picocli through the server's command table. */
    public static final class History {
        @Parameters(index = "0", paramLabel = "MAILBOX")
        String mailbox;
        @Option(names = "--last", paramLabel = "N", converter = OptionValues.Count.class)
        int last;
        @Option(names = "--since", paramLabel = "ISO-TIME", converter = OptionValues.IsoTime.class)
        Instant since;
    }

    /** {@code ?history MAILBOX [--last N] [--since ISO-TIME]}, its words already read. */
    public OutgoingServerMessage history(IncomingServerMessage request, String fid, History h) throws IOException {
        String user = request.header().origin().user();
        String mailbox;
        try {
            mailbox = MailboxAddress.parse(h.mailbox).toString();
        } catch (IllegalArgumentException e) {
            return error(request, fid, ErrorCode.UNKNOWN_MAILBOX, e.getMessage());
        }
        int last = h.last;
        Instant since = h.since;
        String why = Rights.whyNotRead(permits.get(), user, mailbox);
        if (why != null) {
            return error(request, fid, ErrorCode.FORBIDDEN, why);
        }
        if (last == 0 && since == null) {
            last = 100;
        }
        Transcript.Page page = hub.history(mailbox, since, last);
        StringBuilder b = new StringBuilder();
        b.append(page.entries().size()).append(" entr").append(page.entries().size() == 1 ? "y" : "ies").append(" of ")
                .append(mailbox);
        if (page.more()) {
            b.append(since != null && last == 0 ? " (more after these: ask again with --since the last time shown)"
                    : " (older ones left out)");
        }
        if (page.unreadable() > 0) {
            b.append(" (").append(page.unreadable()).append(" unreadable transcript lines skipped)");
        }
        String trouble = hub.transcriptTrouble();
        if (trouble != null) {
            b.append("\nwarning: ").append(trouble);
        }
        for (ConsoleEntry e : page.entries()) {
            b.append('\n').append(Entries.toText(e));
        }
        return request.reply(Footer.ok(fid, b.toString(), new ConsoleBatch(mailbox, page.entries(), 0, page.more())).via(via));
    }

    static String describe(SessionState s) {
        if (s == null) {
            return " (nothing heard from it yet)";
        }
        StringBuilder b = new StringBuilder(" (").append(s.state().words());
        if (s.lastContact() > 0) {
            b.append(", last contact ").append(Instant.ofEpochMilli(s.lastContact()));
        }
        if (s.hasPosition()) {
            b.append(String.format(Locale.ROOT, ", at %.5f, %.5f", s.lat(), s.lon()));
        }
        return b.append(", ").append(s.calls()).append(s.calls() == 1 ? " call)" : " calls)").toString();
    }

    private static String usage(String word) {
        return switch (word) {
            case "?watch" -> "?watch MAILBOX";
            default -> "?unwatch MAILBOX";
        };
    }

    private OutgoingServerMessage error(IncomingServerMessage request, String fid, ErrorCode code, String text) {
        return request.reply(Footer.error(fid, code, text).via(via));
    }

    /** The words of a MailBox's state for {@code ?mailboxes} and {@code ?status}. */
    public static String describeState(SessionState s) {
        return s == null ? "" : describe(s).substring(1);
    }
}
