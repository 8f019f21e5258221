package org.ripv.client.cli;

import java.io.PrintStream;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * {@code --password-file} and {@code --password}, as {@code ripv cli} and {@code ripv client} both
 * take them (a picocli mixin): the file's first line, or the password itself with a warning,
 * since every user of the machine sees it in {@code ps}; never both.
 */
public final class PasswordOptions {
    @Option(names = "--password-file", paramLabel = "FILE", description = "File whose first line is the password.")
    Path file;

    @Option(names = "--password", paramLabel = "PASSWORD",
            description = "The password (other users see it in ps: prefer --password-file).")
    String password;

    /**
     * The password the command line gives, or null when it gives none.
     *
     * @param instead what the warning about {@code --password} recommends
     * @throws IllegalArgumentException when both options are given
     * @throws PasswordFile.Unusable    when the file cannot give a password
     */
    public char[] given(PrintStream err, String instead) throws PasswordFile.Unusable {
        if (password != null && file != null) {
            throw new IllegalArgumentException("give --password or --password-file, not both");
        }
        if (password != null) {
            err.println("Warning: --password shows the password to every user of this machine (ps); use " + instead);
            return password.toCharArray();
        }
        return file == null ? null : PasswordFile.read(file);
    }

    /** Whether either option was given. */
    public boolean any() {
        return password != null || file != null;
    }
}
