package org.ripv.server.vehicles;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;
import org.ripv.commands.SingleLineCommand;
import org.ripv.naming.MailboxAddress;

/**
 * Turns what a user typed where a MailBox is expected into a full MailBox address. A full
 * address ({@code <SerialPortServer>::<localhost>sim01}) is taken as it is; anything else is a
 * vehicle name or handle, looked up among the MailBoxes the services list: exactly one MailBox
 * with that handle is taken, then one whose handle differs only in case (the simulator and the
 * docs do not always agree on case). None or several is an error that says what to type instead.
 */
public final class VehicleNames {
    private VehicleNames() {
    }

    /** The outcome: the full address, or why there is none (an error for the user). */
    public record Resolution(String address, String error) {
        static Resolution of(String address) {
            return new Resolution(address, null);
        }

        static Resolution refused(String why) {
            return new Resolution(null, why);
        }

        public boolean resolved() {
            return address != null;
        }
    }

    /** True when the word is a full address already (no look-up needed to use it). */
    public static boolean isFullAddress(String word) {
        return word.startsWith("<");
    }

    /**
     * Resolves {@code word} against {@code known} (full MailBox addresses; malformed ones are
     * skipped). {@code notAnswering} names the services that did not list their MailBoxes, so
     * that an unknown name can say where it might be.
     */
    public static Resolution resolve(String word, Collection<String> known, Collection<String> notAnswering) {
        if (isFullAddress(word)) {
            try {
                return Resolution.of(MailboxAddress.parse(word).toString());
            } catch (IllegalArgumentException e) {
                return Resolution.refused(e.getMessage());
            }
        }
        List<MailboxAddress> boxes = parsed(known);
        List<String> exact = new ArrayList<>();
        List<String> anyCase = new ArrayList<>();
        for (MailboxAddress a : boxes) {
            if (a.handle().equals(word)) {
                exact.add(a.toString());
            } else if (a.handle().toLowerCase(Locale.ROOT).equals(word.toLowerCase(Locale.ROOT))) {
                anyCase.add(a.toString());
            }
        }
        List<String> matches = exact.isEmpty() ? anyCase : exact;
        if (matches.size() == 1) {
            return Resolution.of(matches.get(0));
        }
        if (matches.size() > 1) {
            return Resolution.refused("'" + word + "' names " + matches.size() + " MailBoxes: " + String.join(", ", matches)
                    + "; give the full address of the one you mean");
        }
        return Resolution.refused("no vehicle or MailBox is called '" + shown(word) + "'; " + whatThereIs(boxes, notAnswering));
    }

    /** The names a user can give, for an error: "the names are: ru29, sim01; ?mailboxes lists the full addresses". */
    public static String whatThereIs(Collection<String> known, Collection<String> notAnswering) {
        return whatThereIs(parsed(known), notAnswering);
    }

    private static List<MailboxAddress> parsed(Collection<String> known) {
        List<MailboxAddress> boxes = new ArrayList<>();
        for (String k : known) {
            try {
                boxes.add(MailboxAddress.parse(k));
            } catch (IllegalArgumentException ignored) {
                // a service's malformed MailBox cannot be named
            }
        }
        return boxes;
    }

    private static String whatThereIs(List<MailboxAddress> boxes, Collection<String> notAnswering) {
        TreeSet<String> names = new TreeSet<>();
        boxes.forEach(a -> names.add(a.handle()));
        StringBuilder b = new StringBuilder(names.isEmpty() ? "no service lists any MailBox now"
                : "the names are: " + String.join(", ", names));
        if (!notAnswering.isEmpty()) {
            b.append(" (not answering, so not asked: ").append(String.join(", ", notAnswering)).append(')');
        }
        return b.append("; ?mailboxes lists the full addresses").toString();
    }

    /** The word as quoted in an error: short, and nothing that could pass for a line of its own. */
    private static String shown(String word) {
        return SingleLineCommand.shown(word);
    }
}
