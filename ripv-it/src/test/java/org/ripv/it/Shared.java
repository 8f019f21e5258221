package org.ripv.it;

/**
 * What test classes of this module share beyond their own ports and folders, as JUnit resource
 * names for {@code @ResourceLock}. The module runs its test classes concurrently (issue 38; the
 * parent pom's {@code ripv.test.parallelism}); a class that holds one of these runs beside any
 * class except another holding the same. A class that changes the whole JVM (system properties
 * read by every in-process server) is {@code @Isolated} instead.
 */
public final class Shared {
    /**
     * The one display (Xvfb in CI): AssertJ-Swing's robot moves the one mouse and keyboard focus,
     * so two windows driven at once take each other's keys.
     */
    public static final String DISPLAY = "ripv.display";

    /**
     * Network namespaces: {@link Netns} names them after this JVM's process id, so two sets made
     * at once in one JVM would be the same names.
     */
    public static final String NETNS = "ripv.netns";

    /**
     * Both cores: a class that loads the machine on purpose (a thousand clients, every benchmark's
     * short run, a whole Maven build) runs beside waiting tests but not beside another such class,
     * which would only make both slower and their deadlines tighter.
     */
    public static final String CPU = "ripv.cpu";

    /**
     * A headless Chromium: a browser loads both cores while it renders, and a page waited for on a
     * machine running two others besides the tests' servers missed its 90 s (issue 38's first
     * parallel run). One browser test class at a time; the rest of the suite runs beside it.
     */
    public static final String BROWSER = "ripv.browser";

    private Shared() {}
}
