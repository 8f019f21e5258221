package org.ripv.it;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;

/**
 * The {@code java} command line tests start the product's jars with: the same jars, with flags for
 * JVMs that live seconds. The suite is CPU-bound on a 2-core machine and starts hundreds of such
 * JVMs; each would otherwise spend CPU on C2 compilation of code it runs only a few times and on
 * G1's concurrent threads for a heap it never fills. C1 only ({@code -XX:TieredStopAtLevel=1}), the
 * serial collector and the shared class archive cut that (ripv-it's {@code Netns} and ripv-services'
 * {@code SeedInChild} already launch this way). The product's launcher and {@code ./ripv bench}
 * outside tests keep the product's own options (the server's {@code ServerMain.JVM_OPTIONS}, which
 * this executable's collector replaces: java refuses two); the benchmarks' figures are not taken here.
 * {@code -Dripv.test.plainJvms=true} launches with the defaults instead (to measure what this saves).
 */
public final class TestJvms {
    /** The flags, or none when {@code ripv.test.plainJvms} is set. */
    static final List<String> FLAGS = Boolean.getBoolean("ripv.test.plainJvms") ? List.of()
            : List.of("-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-Xshare:auto");

    private static Path launcherJava;

    private TestJvms() {
    }

    /**
     * The {@code java} to launch: an executable that runs the running JDK's {@code java FLAGS… "$@"}
     * (it execs, so the process is the JVM), written once per test JVM under {@code target/}. One
     * path, so it fits wherever a test names {@code java}, and the {@code ripv} launcher's {@code $JAVA}.
     */
    public static synchronized String java() {
        if (launcherJava == null) {
            try {
                Path dir = Files.createDirectories(Path.of("target").toAbsolutePath());
                Path script = Files.createTempFile(dir, "test-java-", ".sh",
                        PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
                String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
                StringBuilder line = new StringBuilder("exec '" + java + "'");
                FLAGS.forEach(f -> line.append(' ').append(f));
                // These flags pick the collector: one the launcher gives the JVM (./ripv server's
                // -XX:+UseParallelGC, ServerMain.JVM_OPTIONS) is dropped, as java refuses two. Only
                // options before the main class or jar are the JVM's.
                String keepOne = FLAGS.stream().anyMatch(f -> f.matches("-XX:\\+Use\\w+GC")) ? """
                        n=$#; jvm=1
                        while [ "$n" -gt 0 ]; do
                          a=$1; shift; n=$((n - 1))
                          case "$jvm:$a" in
                            1:-XX:+Use*GC) continue ;;
                            1:-*) ;;
                            1:*) jvm=0 ;;
                          esac
                          [ "$a" = -jar ] && jvm=0
                          set -- "$@" "$a"
                        done
                        """ : "";
                Files.writeString(script, "#!/bin/sh\n" + keepOne + line + " \"$@\"\n");
                script.toFile().deleteOnExit();
                launcherJava = script;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return launcherJava.toString();
    }
}
