package org.ripv.handout;

import java.nio.charset.StandardCharsets;
import java.rmi.RemoteException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.ripv.messages.Attachment;
import org.ripv.rmi.GenericRMIInterface;

/**
 * The ingesting service's side: a request whose attachment is a list of tickets
 * ({@link #ATTACHMENT}, one {@code NAME<TAB>TICKET} line per file) gets the files themselves,
 * read from their holders chunk by chunk. Every byte is checked: the list's length, each ticket's
 * shape, that it is meant for this service, the total against a limit before anything is read,
 * each chunk's length, and the SHA-256 the server signed. Any failure refuses the whole request
 * with a text that starts {@link #REFUSED}, which tells the server to relay the bytes instead.
 */
public final class HandoutCollector {
    /** The name of an attachment that carries tickets instead of bytes. */
    public static final String ATTACHMENT = "handouts.txt";
    /** How a refusal begins, for the server to recognise it. */
    public static final String REFUSED = "handout refused: ";
    /** At most this many files in one list (as many as a bundle may hold). */
    public static final int MAX_FILES = 1000;

    /** Finds the holder named in a ticket: its stub, or null when it cannot be reached directly. */
    @FunctionalInterface
    public interface Peers {
        GenericRMIInterface peer(String service) throws RemoteException;
    }

    private HandoutCollector() {}

    /** A named file and the ticket to read it by. */
    public record Entry(String name, HandoutTicket ticket) {}

    /** The attachment that carries {@code entries} in place of their bytes. */
    public static Attachment attachment(List<Entry> entries) {
        StringBuilder s = new StringBuilder();
        for (Entry e : entries) {
            if (e.name().chars().anyMatch(c -> c < 0x20 || c == 0x7f)) {
                throw new IllegalArgumentException("a file name with a control character: " + e.name());
            }
            s.append(e.name()).append('\t').append(e.ticket().text()).append('\n');
        }
        return new Attachment(ATTACHMENT, s.toString().getBytes(StandardCharsets.UTF_8));
    }

    /** True when an attachment carries tickets. */
    public static boolean carriesTickets(Attachment a) {
        return a != null && a.name().equals(ATTACHMENT);
    }

    /**
     * The files the tickets name, read from their holders: one attachment, a bundle when there
     * are several, as the server would have attached them.
     *
     * @param self     this service's full name: the destination every ticket must name
     * @param maxBytes the most all the files together may hold
     */
    public static Attachment collect(Attachment tickets, Peers peers, String self, long maxBytes) throws HandoutRefused {
        List<Entry> entries = entries(tickets);
        long total = 0;
        for (Entry e : entries) {
            if (!e.ticket().destination().equals(self)) {
                throw new HandoutRefused("the ticket for " + e.name() + " is meant for " + e.ticket().destination()
                        + ", not " + self);
            }
            total += e.ticket().size();
            if (total > maxBytes || e.ticket().size() > Integer.MAX_VALUE - 8) {
                throw new HandoutRefused("the files come to more than " + maxBytes + " bytes");
            }
        }
        Map<String, GenericRMIInterface> holders = new HashMap<>();
        List<Attachment> files = new ArrayList<>();
        for (Entry e : entries) {
            String source = e.ticket().source();
            GenericRMIInterface holder = holders.get(source);
            if (holder == null) {
                try {
                    holder = peers.peer(source);
                } catch (RemoteException | RuntimeException x) {
                    throw new HandoutRefused("cannot learn where " + source + " is: " + x.getMessage(), x);
                }
                if (holder == null) {
                    throw new HandoutRefused(source + " cannot be reached directly (it is not registered, or registered"
                            + " outbound-only)");
                }
                holders.put(source, holder);
            }
            files.add(new Attachment(e.name(), read(holder, e)));
        }
        return files.size() == 1 ? files.get(0) : Attachment.bundle(files);
    }

    private static byte[] read(GenericRMIInterface holder, Entry e) throws HandoutRefused {
        HandoutTicket t = e.ticket();
        byte[] data = new byte[(int) t.size()];
        String text = t.text();
        int at = 0;
        while (at < data.length) { // an empty file reads nothing; the hash below still checks it
            int want = Math.min(Handouts.MAX_CHUNK, data.length - at);
            byte[] chunk;
            try {
                chunk = holder.handout(text, at, want);
            } catch (RemoteException | RuntimeException x) {
                throw new HandoutRefused("could not read " + e.name() + " from " + t.source() + ": " + x.getMessage(), x);
            }
            if (chunk == null || chunk.length == 0 || chunk.length > want) {
                throw new HandoutRefused(t.source() + " sent " + (chunk == null ? "nothing" : chunk.length + " bytes")
                        + " where 1 to " + want + " belonged");
            }
            System.arraycopy(chunk, 0, data, at, chunk.length);
            at += chunk.length;
        }
        if (!HandoutTicket.sha256(data).equals(t.sha256())) {
            throw new HandoutRefused(e.name() + " from " + t.source() + " is not the file the server recorded (SHA-256 differs)");
        }
        return data;
    }

    static List<Entry> entries(Attachment tickets) throws HandoutRefused {
        if (tickets.data().length > MAX_FILES * (HandoutTicket.MAX_TEXT + 512L)) {
            throw new HandoutRefused("the ticket list is too long");
        }
        List<Entry> out = new ArrayList<>();
        for (String line : new String(tickets.data(), StandardCharsets.UTF_8).split("\n")) {
            if (line.isEmpty()) {
                continue;
            }
            int tab = line.indexOf('\t');
            if (tab <= 0 || out.size() == MAX_FILES) {
                throw new HandoutRefused(tab <= 0 ? "a ticket line without a file name" : "more than " + MAX_FILES + " tickets");
            }
            out.add(new Entry(line.substring(0, tab), HandoutTicket.parse(line.substring(tab + 1))));
        }
        if (out.isEmpty()) {
            throw new HandoutRefused("the ticket list is empty");
        }
        return out;
    }
}
