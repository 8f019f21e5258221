package org.ripv.client.managers;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ConsoleLines;
import org.ripv.messages.SessionState;
import org.ripv.messages.VehicleEvent;

/**
 * The live consoles the client watches (docs/sessions.md): per MailBox, the last
 * {@link #MAX_ENTRIES} console entries the server pushed, and the call state they imply. Changed
 * on the UI thread only; panels listen and repaint.
 */
public final class ConsoleModel {
    /** Entries kept per MailBox; older ones are in the server's transcript ({@code ?history}). */
    public static final int MAX_ENTRIES = 5_000;

    /** Told, on the UI thread, that a MailBox's console changed. */
    public interface Listener {
        void changed(String mailbox);
    }

    private final Map<String, ArrayDeque<ConsoleEntry>> entries = new HashMap<>();
    private final Map<String, Long> revisions = new HashMap<>();
    private final List<Listener> listeners = new CopyOnWriteArrayList<>();

    public void addListener(Listener l) {
        listeners.add(l);
    }

    public void removeListener(Listener l) {
        listeners.remove(l);
    }

    /** Adds a batch (a push, or the replay of a {@code ?watch} reply). */
    void add(ConsoleBatch batch) {
        ArrayDeque<ConsoleEntry> list = entries.computeIfAbsent(batch.mailbox(), k -> new ArrayDeque<>());
        for (ConsoleEntry e : batch.entries()) {
            if (!list.isEmpty() && list.peekLast().equals(e)) {
                continue; // a replay repeating what a push already brought
            }
            list.addLast(e);
            if (list.size() > MAX_ENTRIES) {
                list.removeFirst();
            }
        }
        revisions.merge(batch.mailbox(), 1L, Long::sum);
        listeners.forEach(l -> l.changed(batch.mailbox()));
    }

    /**
     * Adds transcript entries ({@code ?history}) before what is shown: those older than the
     * oldest entry kept, so scrolling back never repeats or reorders lines.
     */
    void addHistory(ConsoleBatch batch) {
        ArrayDeque<ConsoleEntry> list = entries.computeIfAbsent(batch.mailbox(), k -> new ArrayDeque<>());
        List<ConsoleEntry> history = batch.entries();
        // Where the transcript meets what is shown: the first entry kept, found by value (times
        // alone collide within a millisecond) but for its number, which the live entry has and the
        // transcript's copy may not; failing that, whatever is strictly older.
        int meet = list.isEmpty() ? history.size() : indexOfUnnumbered(history, list.peekFirst());
        long oldest = list.isEmpty() ? Long.MAX_VALUE : list.peekFirst().time();
        List<ConsoleEntry> older = meet >= 0 ? history.subList(0, meet)
                : history.stream().filter(e -> e.time() < oldest).toList();
        for (int i = older.size() - 1; i >= 0 && list.size() < MAX_ENTRIES; i--) {
            list.addFirst(older.get(i));
        }
        revisions.merge(batch.mailbox(), 1L, Long::sum);
        listeners.forEach(l -> l.changed(batch.mailbox()));
    }

    private static int indexOfUnnumbered(List<ConsoleEntry> history, ConsoleEntry first) {
        ConsoleEntry wanted = first.withSeq(0);
        for (int i = 0; i < history.size(); i++) {
            if (history.get(i).withSeq(0).equals(wanted)) {
                return i;
            }
        }
        return -1;
    }

    public List<ConsoleEntry> entries(String mailbox) {
        ArrayDeque<ConsoleEntry> list = entries.get(mailbox);
        return list == null ? List.of() : List.copyOf(list);
    }

    /** Grows with every change of the MailBox's console (so a panel can skip repainting). */
    public long revision(String mailbox) {
        return revisions.getOrDefault(mailbox, 0L);
    }

    /** One entry as the console shows it. */
    public static String text(ConsoleEntry e) {
        return ConsoleLines.withClock(e);
    }

    /** A state badge for people: {@code ● on call · last contact 12 min ago}; empty when unknown. */
    public static String badge(SessionState s, Instant now) {
        if (s == null) {
            return "";
        }
        String dot = switch (s.state()) {
            case ON_CALL -> "●";
            case DIVED -> "○";
            case LOST -> "✕";
            case UNKNOWN -> "?";
        };
        String b = dot + " " + s.state().words();
        if (s.lastContact() > 0) {
            b += " · last contact " + ago(Duration.between(Instant.ofEpochMilli(s.lastContact()), now));
        }
        return b;
    }

    static String ago(Duration d) {
        long s = Math.max(0, d.toSeconds());
        if (s < 60) {
            return "just now";
        }
        if (s < 3600) {
            return s / 60 + " min ago";
        }
        if (s < 86_400) {
            return s / 3600 + " h ago";
        }
        return s / 86_400 + " d ago";
    }

    /** True for the events that deserve a desktop notification. */
    static boolean notifies(ConsoleEntry e) {
        return e.kind() == ConsoleEntry.Kind.EVENT && (e.event() == VehicleEvent.SURFACED || e.event() == VehicleEvent.ALERT);
    }
}
