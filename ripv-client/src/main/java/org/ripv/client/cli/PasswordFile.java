package org.ripv.client.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

/**
 * A {@code --password-file}: its first line is the password. Each way it can be unusable gets a
 * message that says how to make a good one (docs/operations.md#ripv-cli).
 */
public final class PasswordFile {
    private PasswordFile() {}

    /** The unusable file, with what to do about it. */
    public static final class Unusable extends IOException {
        Unusable(String message, Throwable cause) {
            super(message, cause);
        }
    }

    /** The password on the file's first line (without its line end). */
    public static char[] read(Path file) throws Unusable {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new Unusable("the password file " + file + " does not exist: make it readable by you only with"
                    + "  install -m 600 /dev/null " + file + "  and write the password on its first line", e);
        } catch (IOException e) {
            throw new Unusable("cannot read the password file " + file + ": " + e, e);
        }
        int nl = text.indexOf('\n');
        String line = nl < 0 ? text : text.substring(0, nl);
        if (line.endsWith("\r")) {
            line = line.substring(0, line.length() - 1);
        }
        if (line.isEmpty()) {
            throw new Unusable("the password file " + file + " has no password on its first line: write it there", null);
        }
        return line.toCharArray();
    }
}
