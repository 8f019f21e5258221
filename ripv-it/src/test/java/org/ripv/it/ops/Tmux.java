package org.ripv.it.ops;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/** A tmux server of its own (its own socket), to type into a program on a real terminal and read the screen. */
final class Tmux implements AutoCloseable {
    private final String socket = "ripv-test-" + UUID.randomUUID();
    private final String session = "t";

    Tmux(int columns, int rows, String... command) throws IOException, InterruptedException {
        List<String> args = new ArrayList<>(List.of("new-session", "-d", "-s", session, "-x", "" + columns, "-y", "" + rows));
        args.addAll(List.of(command));
        tmux(args.toArray(String[]::new));
    }

    /** Types text literally (no key names). */
    void type(String text) throws IOException, InterruptedException {
        tmux("send-keys", "-t", session, "-l", text);
    }

    /** Presses keys by tmux name: Enter, Tab, Up, C-c, C-d. */
    void keys(String... keys) throws IOException, InterruptedException {
        List<String> args = new ArrayList<>(List.of("send-keys", "-t", session));
        args.addAll(List.of(keys));
        tmux(args.toArray(String[]::new));
    }

    String screen() throws IOException, InterruptedException {
        return tmux("capture-pane", "-p", "-J", "-t", session);
    }

    /** Everything the terminal showed, the lines scrolled off the top too (its history, then the screen). */
    String scrollback() throws IOException, InterruptedException {
        return tmux("capture-pane", "-p", "-J", "-S", "-", "-t", session);
    }

    /** As {@link #await}, on the whole scrollback: for text that may have scrolled off a busy screen meanwhile. */
    String awaitInScrollback(String what, Duration max, Predicate<String> test) throws IOException, InterruptedException {
        long end = System.nanoTime() + max.toNanos();
        String s = scrollback();
        while (!test.test(s)) {
            if (System.nanoTime() > end) {
                throw new AssertionError("timed out waiting for " + what + "; the terminal:\n" + s);
            }
            Thread.sleep(50);
            s = scrollback();
        }
        return s;
    }

    /** Waits until the screen satisfies the test; fails with the screen after the time is up. */
    String await(String what, Duration max, Predicate<String> test) throws IOException, InterruptedException {
        long end = System.nanoTime() + max.toNanos();
        String s = screen();
        while (!test.test(s)) {
            if (System.nanoTime() > end) {
                throw new AssertionError("timed out waiting for " + what + "; the screen:\n" + s);
            }
            Thread.sleep(50);
            s = screen();
        }
        return s;
    }

    String awaitText(String text) throws IOException, InterruptedException {
        return await("'" + text + "'", Duration.ofSeconds(20), s -> s.contains(text));
    }

    /** The last non-empty line on the screen (where the cursor's prompt is). */
    static String lastLine(String screen) {
        String[] lines = screen.stripTrailing().split("\n");
        return lines[lines.length - 1];
    }

    private String tmux(String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of("tmux", "-L", socket, "-f", "/dev/null"));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(10, TimeUnit.SECONDS) || p.exitValue() != 0) {
            throw new IOException("tmux " + String.join(" ", args) + " failed: " + out);
        }
        return out;
    }

    @Override
    public void close() throws IOException, InterruptedException {
        try {
            tmux("kill-server");
        } catch (IOException e) {
            // already gone with its last session
        }
    }
}
