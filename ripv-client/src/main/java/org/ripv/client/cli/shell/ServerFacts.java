package org.ripv.client.cli.shell;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.FileListing;
import org.ripv.messages.MailboxList;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.Status;
import org.ripv.naming.MailboxAddress;

/**
 * Completion's facts, asked of the server when Tab needs them and kept a few seconds (lists that
 * change: MailBoxes, files) or for the session (commands). A slow or failed answer completes
 * nothing rather than holding up the terminal.
 */
final class ServerFacts implements Facts {
    private static final Duration WAIT = Duration.ofSeconds(3);
    private static final long LIST_MILLIS = 5_000;

    private record Cached(List<String> values, long at) {}

    private final ClientSocketHandler client;
    private final Map<String, Cached> cache = new ConcurrentHashMap<>();

    ServerFacts(ClientSocketHandler client) {
        this.client = client;
    }

    @Override
    public List<String> serverCommands() {
        return cached("?help", Long.MAX_VALUE, "", "?help", r -> {
            List<String> out = new ArrayList<>();
            for (String line : r.footer().replyText().split("\n")) {
                String w = line.strip().split("\\s+", 2)[0];
                if (w.startsWith("?") && w.length() > 1) {
                    out.add(w);
                }
            }
            return out;
        });
    }

    @Override
    public List<String> serverOptions(String command) {
        return Completions.optionsIn(helpText(), command);
    }

    @Override
    public boolean serverTakesMailbox(String command) {
        return Completions.takesMailboxIn(helpText(), command);
    }

    /** {@code ?help}'s text: one line a server command, written by the server from its command table. */
    private String helpText() {
        return String.join("\n", cached("?help lines", Long.MAX_VALUE, "", "?help",
                r -> List.of(r.footer().replyText().split("\n"))));
    }

    @Override
    public List<String> mailboxes() {
        return cached("?mailboxes", LIST_MILLIS, "", "?mailboxes", r -> {
            List<String> out = new ArrayList<>();
            if (r.footer().result() instanceof MailboxList l) {
                l.mailboxes().forEach(s -> out.add(s.address()));
            }
            return out;
        });
    }

    @Override
    public List<String> downloads() {
        return cached("?dlfiles", LIST_MILLIS, "", "?dlfiles", ServerFacts::names);
    }

    @Override
    public List<String> uploads() {
        return cached("?ulfiles", LIST_MILLIS, "", "?ulfiles", ServerFacts::names);
    }

    @Override
    public List<String> serviceCommands(String mailbox) {
        List<String> out = new ArrayList<>(cached("help " + mailbox, Long.MAX_VALUE, mailbox, "help",
                r -> Completions.commandsIn(r.footer().replyText())));
        out.addAll(attachPrefixes(mailbox));
        return out;
    }

    @Override
    public List<String> attachPrefixes(String mailbox) {
        String service;
        try {
            service = MailboxAddress.parse(mailbox).service().toString();
        } catch (IllegalArgumentException e) {
            return List.of();
        }
        List<String> out = new ArrayList<>();
        for (String d : cached("?services", Long.MAX_VALUE, "", "?services", ServerFacts::descriptors)) {
            int tab = d.indexOf('\t');
            if (d.substring(0, tab).equals(service) && tab < d.length() - 1) {
                out.addAll(List.of(d.substring(tab + 1).split("\t")));
            }
        }
        return out;
    }

    /** "NAME\tPREFIX\tPREFIX..." per service. */
    private static List<String> descriptors(OutgoingServerMessage r) {
        List<String> out = new ArrayList<>();
        if (r.footer().result() instanceof ServiceList l) {
            for (ServiceDescriptor d : l.services()) {
                out.add(d.name() + "\t" + String.join("\t", d.attachPrefixes()));
            }
        }
        return out;
    }

    private static List<String> names(OutgoingServerMessage r) {
        List<String> out = new ArrayList<>();
        if (r.footer().result() instanceof FileListing l) {
            l.files().forEach(e -> out.add(e.name()));
        }
        return out;
    }

    private List<String> cached(String key, long maxAgeMillis, String mailbox, String body,
                                Function<OutgoingServerMessage, List<String>> read) {
        long now = System.currentTimeMillis();
        Cached c = cache.get(key);
        if (c != null && now - c.at() < maxAgeMillis) {
            return c.values();
        }
        List<String> values;
        try {
            OutgoingServerMessage r = client.call(mailbox, body, Priority.NORMAL, WAIT, null);
            values = r.status() == Status.ERROR ? List.of() : List.copyOf(read.apply(r));
        } catch (IOException e) {
            return c == null ? List.of() : c.values(); // try again at the next Tab
        }
        cache.put(key, new Cached(values, now));
        return values;
    }
}
