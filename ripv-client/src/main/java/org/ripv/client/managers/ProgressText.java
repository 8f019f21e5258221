package org.ripv.client.managers;

import java.util.Locale;
import org.ripv.messages.Progress;

/** How progress reads for people: sizes, rate and time left ({@code 0:52 left}). */
public final class ProgressText {
    private ProgressText() {
    }

    /** "ymodem:get LOG  12 KB / 64 KB  1 KB/s  0:52 left". */
    public static String of(Progress p) {
        return of(p.what(), p);
    }

    /**
     * As {@link #of(Progress)}, led by the command that runs: "ymodem:get *.SBD · 01230000.SBD  12 KB
     * / 20 KB …" (the item the progress is about follows when the command does not name it).
     */
    public static String of(String command, Progress p) {
        StringBuilder b = new StringBuilder(label(command, p)).append("  ").append(Transfer.size(p.done()));
        if (p.total() > 0) {
            b.append(" / ").append(Transfer.size(p.total()));
        }
        if (p.ratePerSecond() > 0) {
            b.append("  ").append(Transfer.size((long) p.ratePerSecond())).append("/s");
        }
        String eta = eta(p);
        if (!eta.isEmpty()) {
            b.append("  ").append(eta).append(" left");
        }
        return b.toString();
    }

    /** The command, and the item the progress is about when the command does not name it. */
    static String label(String command, Progress p) {
        return command == null || command.isBlank() ? p.what()
                : p.what().isBlank() || command.contains(p.what()) ? command : command + " · " + p.what();
    }

    /** Time left at the reported rate ({@code 1:12}), or empty when unknown (no rate, no total, done). */
    public static String eta(Progress p) {
        if (p.ratePerSecond() <= 0 || p.total() <= p.done()) {
            return "";
        }
        return clock((long) Math.ceil((p.total() - p.done()) / p.ratePerSecond()));
    }

    /** Seconds as {@code M:SS}, or {@code H:MM:SS} from an hour. */
    public static String clock(long seconds) {
        long s = Math.max(0, seconds);
        return s >= 3600 ? String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60)
                : String.format(Locale.ROOT, "%d:%02d", s / 60, s % 60);
    }
}
