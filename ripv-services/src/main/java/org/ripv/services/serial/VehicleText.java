package org.ripv.services.serial;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reading a vehicle's side of a conversation: where it echoed the command line back, whether it
 * is at its prompt again, and the reply with both cut away.
 */
final class VehicleText {
    private final Pattern prompt;

    VehicleText(Pattern prompt) {
        this.prompt = prompt;
    }

    /** Where the echoed command line ends in {@code text}, or -1 if it has not been echoed. */
    static int echoEnd(CharSequence text, String command) {
        String t = text.toString();
        int from = 0;
        while (true) {
            int i = t.indexOf(command, from);
            if (i < 0) {
                return -1;
            }
            int after = i + command.length();
            if (after < t.length() && (t.charAt(after) == '\r' || t.charAt(after) == '\n')) {
                return t.charAt(after) == '\r' && after + 1 < t.length() && t.charAt(after + 1) == '\n'
                        ? after + 2 : after + 1;
            }
            from = i + 1;
        }
    }

    /** True when the vehicle has echoed {@code command} and is back at its prompt after it. */
    boolean promptAfterEcho(CharSequence text, String command) {
        int end = echoEnd(text, command);
        return end >= 0 && endsWithPrompt(text.subSequence(end, text.length()));
    }

    boolean endsWithPrompt(CharSequence text) {
        int from = Math.max(0, text.length() - 256);
        Matcher m = prompt.matcher(text.subSequence(from, text.length()));
        while (m.find()) {
            if (text.subSequence(from + m.end(), text.length()).toString().isBlank()) {
                return true;
            }
        }
        return false;
    }

    /** Drops the echoed command line at the start and the prompt at the end. */
    String clean(String raw, String command) {
        int echo = echoEnd(raw, command);
        String s = echo >= 0 ? raw.substring(echo) : raw;
        int from = Math.max(0, s.length() - 256);
        Matcher m = prompt.matcher(s);
        int cut = -1;
        if (m.find(from)) {
            do {
                if (s.substring(m.end()).isBlank()) {
                    cut = m.start();
                    break;
                }
            } while (m.find());
        }
        if (cut >= 0) {
            s = s.substring(0, cut);
        }
        return s.replace("\r\n", "\n").replace('\r', '\n').stripTrailing();
    }
}
