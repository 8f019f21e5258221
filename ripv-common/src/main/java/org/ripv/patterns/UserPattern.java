package org.ripv.patterns;

import com.google.re2j.Matcher;
import com.google.re2j.Pattern;
import com.google.re2j.PatternSyntaxException;

/**
 * A regular expression a user or operator wrote, matched in linear time (RE2/J): no
 * back-references or look-around, which are what make a backtracking match exponential.
 *
 * @param text    the pattern as written
 * @param pattern the compiled pattern
 */
public record UserPattern(String text, Pattern pattern) {
    /** Longer patterns are refused: compiling one costs memory in proportion to its length. */
    public static final int MAX_LENGTH = 1_000;

    /**
     * Compiles a pattern, or explains what is wrong with it.
     *
     * @param what what the pattern is for, for the message ({@code "expect="}, {@code "wait-for"})
     * @throws IllegalArgumentException quoting the pattern and saying what to change
     */
    public static UserPattern compile(String what, String text) {
        return compile(what, text, 0);
    }

    /** As {@link #compile(String, String)}, with RE2/J flags ({@link Pattern#CASE_INSENSITIVE}, ...). */
    public static UserPattern compile(String what, String text, int flags) {
        if (text == null) {
            throw new IllegalArgumentException(what + ": no pattern given");
        }
        if (text.length() > MAX_LENGTH) {
            throw new IllegalArgumentException(what + " '" + text.substring(0, 40) + "…' is " + text.length()
                    + " characters; a pattern may have at most " + MAX_LENGTH);
        }
        try {
            return new UserPattern(text, Pattern.compile(text, flags));
        } catch (PatternSyntaxException e) {
            throw new IllegalArgumentException(what + " '" + text + "' is not a regular expression RIPV takes: "
                    + e.getDescription() + " (RE2 syntax: no back-references or look-around)");
        } catch (RuntimeException e) {
            // RE2/J refuses some patterns (a repeat over 1,000, a program too large) with other exceptions.
            throw new IllegalArgumentException(what + " '" + text + "' is not a regular expression RIPV takes: " + e.getMessage());
        }
    }

    /** True when the pattern occurs somewhere in the text. */
    public boolean find(CharSequence s) {
        return pattern.matcher(s).find();
    }

    /** A matcher, for groups. */
    public Matcher matcher(CharSequence s) {
        return pattern.matcher(s);
    }

    @Override
    public String toString() {
        return text;
    }
}
