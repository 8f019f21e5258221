package org.ripv.commands;

import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * A service's commands by their first word, each named once with its usage and help, in the order
 * they were added: what routing looks a command up in, and what usage messages and help are
 * written from, so that a command added here is known to all of them. The server's {@code ?}
 * commands ({@code org.ripv.server.commands.CommandTable}) and a serial link's
 * ({@code org.ripv.services.serial.LinkCommands}) have this shape.
 *
 * @param <C> what the table holds: a word, a usage line, a help line, and whatever runs it
 */
public final class WordTable<C extends WordTable.Word> {
    /** One entry: the word it is found by, and what help and usage messages say of it. */
    public interface Word {
        /** The command word ({@code ymodem:get}, {@code ?key}). */
        String word();

        /** The command with its arguments, for usage messages ({@code ymodem:get NAME…}). */
        String usage();

        /** One line of help. */
        String help();
    }

    private final Map<String, C> words = new LinkedHashMap<>();
    private final boolean ignoreCase;

    private WordTable(boolean ignoreCase) {
        this.ignoreCase = ignoreCase;
    }

    /** Words matched as written. */
    public static <C extends Word> WordTable<C> exact() {
        return new WordTable<>(false);
    }

    /** Words matched in any case (kept in lower case). */
    public static <C extends Word> WordTable<C> ignoringCase() {
        return new WordTable<>(true);
    }

    /** Adds an entry; a word may be named once. */
    public WordTable<C> add(C c) {
        String w = key(c.word());
        if (w.isEmpty() || w.chars().anyMatch(Character::isWhitespace)) {
            throw new IllegalArgumentException("a command word is one word, not '" + c.word() + "'");
        }
        if (words.putIfAbsent(w, c) != null) {
            throw new IllegalArgumentException("the command " + c.word() + " is named twice");
        }
        return this;
    }

    /** The entry a command word names. */
    public Optional<C> find(String word) {
        return Optional.ofNullable(words.get(key(word)));
    }

    /** The entry the first word of a command line names. */
    public Optional<C> forLine(String line) {
        return find(firstWord(line));
    }

    public Collection<C> all() {
        return words.values();
    }

    /** The entries whose word starts with {@code prefix} ({@code ymodem:}), in table order. */
    public List<C> under(String prefix) {
        String p = key(prefix);
        return words.entrySet().stream().filter(e -> e.getKey().startsWith(p)).map(Map.Entry::getValue).toList();
    }

    /** The usages of the entries under {@code prefix}, joined: {@code ymodem:get NAME… or ymodem:put NAME}. */
    public String usages(String prefix) {
        return String.join(" or ", under(prefix).stream().map(Word::usage).toList());
    }

    /** The first word of a command line ("" for a blank one). */
    public static String firstWord(String line) {
        String t = line.strip();
        int end = 0;
        while (end < t.length() && !Character.isWhitespace(t.charAt(end))) {
            end++;
        }
        return t.substring(0, end);
    }

    private String key(String word) {
        return ignoreCase ? word.toLowerCase(Locale.ROOT) : word;
    }
}
