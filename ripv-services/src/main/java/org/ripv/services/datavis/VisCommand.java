package org.ripv.services.datavis;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A parsed {@code vis:NAME [option=value]...} command. Options override the data file's own
 * {@code %} label lines: {@code out=NAME} (the JPEG's name, without .jpg), {@code title=},
 * {@code xlabel=}, {@code ylabel=}, {@code legend=a|b|c}, {@code size=WIDTHxHEIGHT}. A value with
 * spaces goes in double quotes: {@code title="Glider 12, dive 3"}.
 *
 * @param file   the data file's name in the server's upload directory
 * @param output the output name (no extension)
 * @param labels the label overrides
 */
public record VisCommand(String file, String output, PlotLabels labels) {
    /** The command prefix. */
    public static final String PREFIX = "vis:";
    private static final Pattern SIZE = Pattern.compile("(\\d{1,5})[xX](\\d{1,5})");

    /**
     * Parses a command line.
     *
     * @throws IllegalArgumentException with a message for the operator
     */
    public static VisCommand parse(String command) {
        String c = command.strip();
        if (!c.regionMatches(true, 0, PREFIX, 0, PREFIX.length())) {
            throw new IllegalArgumentException("not a vis: command: '" + c + "'");
        }
        List<String> words = words(c.substring(PREFIX.length()));
        if (words.isEmpty()) {
            throw new IllegalArgumentException("vis: needs a data file: vis:NAME [title=\"...\"] [out=NAME] ...");
        }
        String file = words.get(0);
        String output = defaultOutput(file);
        PlotLabels labels = PlotLabels.NONE;
        for (String w : words.subList(1, words.size())) {
            int eq = w.indexOf('=');
            if (eq <= 0) {
                throw new IllegalArgumentException("'" + w + "' is not option=value; options are out, title, xlabel, ylabel, legend, size");
            }
            String key = w.substring(0, eq).toLowerCase(Locale.ROOT);
            String value = w.substring(eq + 1);
            switch (key) {
                case "out", "output" -> {
                    String o = value.replaceFirst("(?i)\\.jpe?g$", "");
                    if (!Exchange.validOutputName(o)) {
                        throw new IllegalArgumentException("out='" + value + "' is not a usable name: use letters, digits, '_' and '-' (at most 100)");
                    }
                    output = o;
                }
                case "title", "xlabel", "ylabel", "legend" -> labels = labels.with(key, value);
                case "size" -> {
                    Matcher m = SIZE.matcher(value);
                    if (!m.matches()) {
                        throw new IllegalArgumentException("size='" + value + "' is not WIDTHxHEIGHT, e.g. size=1024x768");
                    }
                    labels = labels.withSize(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)));
                }
                default -> throw new IllegalArgumentException("unknown option '" + key
                        + "'; options are out, title, xlabel, ylabel, legend, size");
            }
        }
        return new VisCommand(file, output, labels);
    }

    /** The data file's name without its extension, made safe: {@code glider-temp.dat} gives {@code glider-temp}. */
    static String defaultOutput(String file) {
        String base = file.replaceAll(".*[/\\\\]", "");
        int dot = base.lastIndexOf('.');
        if (dot > 0) {
            base = base.substring(0, dot);
        }
        base = base.replaceAll("[^A-Za-z0-9_\\-]", "_").replaceAll("^[_\\-]+", "");
        if (base.isEmpty()) {
            base = "plot";
        }
        return base.length() > 80 ? base.substring(0, 80) : base;
    }

    /** Splits on white space, keeping "double quoted" stretches (quotes removed) together. */
    static List<String> words(String s) {
        List<String> out = new ArrayList<>();
        StringBuilder cur = new StringBuilder();
        boolean quoted = false;
        boolean any = false;
        for (int i = 0; i < s.length(); i++) {
            char ch = s.charAt(i);
            if (ch == '"') {
                quoted = !quoted;
                any = true;
            } else if (Character.isWhitespace(ch) && !quoted) {
                if (any) {
                    out.add(cur.toString());
                    cur.setLength(0);
                    any = false;
                }
            } else {
                cur.append(ch);
                any = true;
            }
        }
        if (quoted) {
            throw new IllegalArgumentException("a double quote is not closed in '" + s.strip() + "'");
        }
        if (any) {
            out.add(cur.toString());
        }
        return out;
    }
}
