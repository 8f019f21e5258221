package org.ripv.testing;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Assumptions;

/**
 * Gate for tests that need a system tool (lrzsz, socat, octave-cli, xvfb...). On a developer's
 * machine without the tool the test is skipped with a reason; where {@code RIPV_REQUIRE_TOOLS}
 * is set (CI, whose .ci/run installs them) a missing tool fails the test instead, so CI can never
 * go green by skipping.
 */
public final class Tools {
    private Tools() {}

    /** Skips (or, in CI, fails) unless every command is on the PATH. */
    public static void require(String... commands) {
        List<String> missing = new ArrayList<>();
        for (String c : commands) {
            if (!onPath(c)) {
                missing.add(c);
            }
        }
        if (missing.isEmpty()) {
            return;
        }
        String why = "needs " + String.join(", ", missing) + " on the PATH (apt-get install lrzsz socat octave xvfb; .ci/run does)";
        if (System.getenv("RIPV_REQUIRE_TOOLS") != null) {
            throw new AssertionError("RIPV_REQUIRE_TOOLS is set but this test " + why);
        }
        Assumptions.abort(why);
    }

    public static boolean onPath(String command) {
        String path = System.getenv("PATH");
        if (path == null) {
            return false;
        }
        for (String dir : path.split(File.pathSeparator)) {
            Path p = Path.of(dir, command);
            if (Files.isRegularFile(p) && Files.isExecutable(p)) {
                return true;
            }
        }
        return false;
    }
}
