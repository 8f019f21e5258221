package org.ripv.launch;

import java.io.IOException;
import java.io.InputStream;
import java.util.Properties;
import picocli.CommandLine.IVersionProvider;

/**
 * The version and git commit baked into {@code org/ripv/launch/version.properties} by the build
 * (ripv-common's pom runs {@code git rev-parse}; "unknown" when git or the repository was absent).
 */
public final class Version {
    private static final Properties PROPS = load();

    private Version() {}

    /** The Maven version, e.g. {@code 1.0.0-SNAPSHOT}. */
    public static String version() {
        return PROPS.getProperty("version", "unknown");
    }

    /** The abbreviated git commit the jars were built from, or {@code unknown}. */
    public static String commit() {
        String c = PROPS.getProperty("commit", "").strip();
        return c.isEmpty() ? "unknown" : c;
    }

    /** {@code RIPV 1.0.0-SNAPSHOT (commit 38fecd619ad5)}. */
    public static String line() {
        return "RIPV " + version() + " (commit " + commit() + ")";
    }

    private static Properties load() {
        Properties p = new Properties();
        try (InputStream in = Version.class.getResourceAsStream("version.properties")) {
            if (in != null) {
                p.load(in);
            }
        } catch (IOException ignored) {
            // an unreadable resource reads as "unknown"
        }
        return p;
    }

    /** For picocli's {@code --version}. */
    public static final class Provider implements IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {line()};
        }
    }

    /** {@code java -cp ripv-common.jar org.ripv.launch.Version}: what {@code ./ripv --version} prints. */
    public static void main(String[] args) {
        System.out.println(line());
    }
}
