package org.ripv.launch;

import java.io.Console;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Where a launcher's password or secret comes from, safest first: a file ({@code --x-file}),
 * an environment variable, the terminal (asked without echo), and last the command line, which
 * still works but warns, since every local user can read a command line with {@code ps}.
 */
public final class Secrets {
    private Secrets() {}

    /**
     * @param value  the value given on the command line, or null
     * @param file   the file given for it ({@code --x-file}), or null; its first line is the secret
     * @param env    the environment variable to try when neither is given
     * @param option the option's name for messages ({@code --db-password})
     * @param ask    whether to ask at the terminal when nothing else gave it (needs a console)
     * @param err    where the warning goes
     * @return the secret, or null when none was given anywhere
     * @throws IllegalArgumentException when both the value and the file are given
     */
    public static String resolve(String value, Path file, String env, String option, boolean ask, PrintStream err)
            throws IOException {
        if (value != null && file != null) {
            throw new IllegalArgumentException("give " + option + " or " + option + "-file, not both");
        }
        if (value != null) {
            err.println("Warning: " + option + " on the command line can be read by every user of this machine (ps);"
                    + " use " + option + "-file FILE" + (env == null ? "" : ", $" + env) + " or the terminal prompt instead");
            return value;
        }
        if (file != null) {
            List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
            return lines.isEmpty() ? "" : lines.get(0).strip();
        }
        String fromEnv = env == null ? null : System.getenv(env);
        if (fromEnv != null && !fromEnv.isEmpty()) {
            return fromEnv;
        }
        Console console = ask ? System.console() : null;
        if (console != null) {
            char[] typed = console.readPassword("%s: ", option.replaceFirst("^--", ""));
            return typed == null || typed.length == 0 ? null : new String(typed);
        }
        return null;
    }
}
