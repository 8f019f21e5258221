package org.ripv.testing;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.ToDoubleFunction;
import org.junit.jupiter.api.ClassDescriptor;
import org.junit.jupiter.api.ClassOrderer;
import org.junit.jupiter.api.ClassOrdererContext;
import org.junit.jupiter.api.parallel.Isolated;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * Orders a module's test classes so that its concurrent run ends when its work does (issue 38):
 * the long classes and those that hold a lock first, longest first, the short free ones last.
 *
 * <p>Why the order matters: JUnit's executor forks every class at once; the other worker threads
 * take them from the front of this list and the thread that forked them from the back. A long class
 * started last runs alone at the end while the other threads idle, and a worker that takes a class
 * whose lock (the browser, the CPU) another class holds waits for it, idle. So:
 * <ol>
 *   <li>{@code @Isolated} classes first (they run alone in any case; JUnit 5.11 runs them after the
 *       rest whatever their place);</li>
 *   <li>then every class that holds a {@code @ResourceLock} or is known to take at least twice the
 *       module's average class, longest first — a locked class counting as long as it and the rest of
 *       its lock's classes together, so that the longest chain of one lock starts first and its lock
 *       is never idle while one of its classes waits — and where the next longest holds the same lock as the
 *       class before it, a class of another lock or none goes between, so that the two front
 *       workers seldom wait on each other;</li>
 *   <li>then the rest, shortest first: the back thread starts on the longest of them, and the
 *       shortest are what is left when the workers meet.</li>
 * </ol>
 *
 * <p>The seconds come from {@value #TIMES}, a copy of a quiet run's {@code target/class-times.txt}
 * ({@link ClassTimes}; only its first two columns are read) in the module's test resources; a class
 * not listed counts as an average one. The order changes the suite's wall time, never what a test
 * checks. (A replay of the scheduling on the quiet run's times put the line between long and short
 * best at about twice the average class in both ripv-it, 15 s a class, and ripv-services, 4 s.)
 */
public final class LongestFirst implements ClassOrderer {
    static final String TIMES = "expected-class-times.txt";
    private final Map<String, Double> seconds;

    public LongestFirst() {
        this(readTimes());
    }

    LongestFirst(Map<String, Double> seconds) {
        this.seconds = seconds;
    }

    @Override
    public void orderClasses(ClassOrdererContext context) {
        @SuppressWarnings("unchecked")
        List<ClassDescriptor> classes = (List<ClassDescriptor>) context.getClassDescriptors();
        double average = classes.stream().map(c -> seconds.get(c.getTestClass().getName())).filter(Objects::nonNull)
                .mapToDouble(Double::doubleValue).average().orElse(1);
        ToDoubleFunction<ClassDescriptor> expected = c -> seconds.getOrDefault(c.getTestClass().getName(), average);
        List<ClassDescriptor> isolated = new ArrayList<>();
        List<ClassDescriptor> front = new ArrayList<>();
        List<ClassDescriptor> back = new ArrayList<>();
        for (ClassDescriptor c : classes) {
            if (c.isAnnotated(Isolated.class)) {
                isolated.add(c);
            } else if (!locks(c).isEmpty() || expected.applyAsDouble(c) >= 2 * average) {
                front.add(c);
            } else {
                back.add(c);
            }
        }
        Comparator<ClassDescriptor> shortestFirst = Comparator.comparingDouble(expected)
                .thenComparing(c -> c.getTestClass().getName());
        isolated.sort(shortestFirst.reversed());
        front.sort(shortestFirst.reversed());
        Map<ClassDescriptor, Double> due = chainLeft(front, expected);
        front.sort(Comparator.comparingDouble((ClassDescriptor c) -> due.get(c)).reversed()
                .thenComparing(shortestFirst.reversed()));
        back.sort(shortestFirst);
        classes.clear();
        classes.addAll(isolated);
        classes.addAll(spaced(front));
        classes.addAll(back);
    }

    /**
     * Per class, how long it and the classes after it still keep its lock busy: its own seconds, or
     * for a locked class the sum over it and the shorter ones of the same lock, whichever is more.
     * The classes of one lock run one after another, so a lock whose classes add up to more than any
     * single class is the run's longest chain: it must start at once and never wait for a worker,
     * or the run ends on its last classes alone (the quiet run of 28 November: the browser classes,
     * 476 s of the module's 735, left the browser idle 259 s while longer free classes went first,
     * and ended on two short browser classes one after the other).
     */
    private static Map<ClassDescriptor, Double> chainLeft(List<ClassDescriptor> longestFirst,
            ToDoubleFunction<ClassDescriptor> expected) {
        Map<ClassDescriptor, Double> due = new HashMap<>();
        Map<String, Double> left = new HashMap<>();
        for (ClassDescriptor c : longestFirst) {
            for (String lock : locks(c)) {
                left.merge(lock, expected.applyAsDouble(c), Double::sum);
            }
        }
        for (ClassDescriptor c : longestFirst) {
            double d = expected.applyAsDouble(c);
            for (String lock : locks(c)) {
                d = Math.max(d, left.get(lock));
                left.merge(lock, -expected.applyAsDouble(c), Double::sum);
            }
            due.put(c, d);
        }
        return due;
    }

    /** Longest first, but never two of one lock in a row while a class of another lock or none is left. */
    private static List<ClassDescriptor> spaced(List<ClassDescriptor> longestFirst) {
        List<ClassDescriptor> left = new ArrayList<>(longestFirst);
        List<ClassDescriptor> out = new ArrayList<>(left.size());
        Set<String> previous = Set.of();
        while (!left.isEmpty()) {
            int pick = 0;
            for (int i = 0; i < left.size(); i++) {
                if (disjoint(previous, locks(left.get(i)))) {
                    pick = i;
                    break;
                }
            }
            ClassDescriptor next = left.remove(pick);
            out.add(next);
            previous = locks(next);
        }
        return out;
    }

    private static boolean disjoint(Set<String> a, Set<String> b) {
        return a.stream().noneMatch(b::contains);
    }

    static Set<String> locks(ClassDescriptor c) {
        Set<String> names = new TreeSet<>();
        for (ResourceLock lock : c.findRepeatableAnnotations(ResourceLock.class)) {
            names.add(lock.value());
        }
        return names;
    }

    private static Map<String, Double> readTimes() {
        Map<String, Double> times = new HashMap<>();
        ClassLoader loader = Thread.currentThread().getContextClassLoader();
        try (InputStream in = (loader != null ? loader : LongestFirst.class.getClassLoader()).getResourceAsStream(TIMES)) {
            if (in == null) {
                return times;
            }
            BufferedReader lines = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
            for (String line; (line = lines.readLine()) != null; ) {
                String[] f = line.trim().split("\\s+");
                if (f.length >= 2 && !f[0].startsWith("#")) {
                    try {
                        times.merge(f[1], Double.parseDouble(f[0]), Math::max);
                    } catch (NumberFormatException notATime) {
                        // a heading or a stray line: the order is a matter of speed, not of correctness
                    }
                }
            }
        } catch (IOException e) {
            // without the times every class counts the same: a slower run, not a wrong one
        }
        return times;
    }
}
