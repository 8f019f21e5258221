package org.ripv.commands;

import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Model.PositionalParamSpec;
import picocli.CommandLine.ParameterException;

/**
 * The words of a {@code ?} command (or one of its subcommands, {@code ?queue add}) read into a
 * picocli-annotated object, by the rules a line from a client needs: it is hostile, so no
 * {@code @file} expansion (that would read the server's disk) and no abbreviated options; options
 * in any case, as command words are. The usage shown beside a refusal is written from the same
 * object, so it cannot drift from what is parsed.
 */
public final class CommandWords {
    private CommandWords() {}

    /**
     * @param usage what a refusal shows after {@code usage: }
     * @return {@code options}, filled from {@code words}
     * @throws IllegalArgumentException picocli's reason and the usage
     */
    public static <T> T parse(T options, String usage, String... words) {
        try {
            new CommandLine(spec(options)).parseArgs(words);
        } catch (ParameterException e) {
            throw new IllegalArgumentException(e.getMessage() + "; usage: " + usage, e);
        }
        return options;
    }

    /** {@code ?history MAILBOX [--last N] [--since ISO-TIME]}: the word, the positional words, then the options. */
    public static String usage(String word, Object options) {
        CommandSpec spec = CommandSpec.forAnnotatedObject(options);
        List<String> parts = new ArrayList<>(List.of(word));
        for (PositionalParamSpec p : spec.positionalParameters()) {
            parts.add(p.required() ? label(p) : "[" + label(p) + "]");
        }
        for (OptionSpec o : spec.options()) {
            String text = o.longestName() + (o.arity().max() > 0 ? " " + label(o) : "");
            parts.add(o.required() ? text : "[" + text + "]");
        }
        return String.join(" ", parts);
    }

    /** The long names of the options (as {@code --last}): what the clients complete. */
    public static List<String> optionNames(Object options) {
        return spec(options).options().stream().map(OptionSpec::longestName).toList();
    }

    private static CommandSpec spec(Object options) {
        CommandSpec spec = CommandSpec.forAnnotatedObject(options);
        spec.parser().expandAtFiles(false).abbreviatedOptionsAllowed(false).caseInsensitiveEnumValuesAllowed(true);
        spec.optionsCaseInsensitive(true);
        return spec;
    }

    private static String label(ArgSpec a) {
        return a.paramLabel().replaceAll("^<|>$", "");
    }
}
