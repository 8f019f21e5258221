package org.ripv.services.simulator;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;

/**
 * The wait after a Slocum's surface dialog: it counts down, saying so every 10 s, and listens
 * for the pilot's control keys — Ctrl-C takes control (GliderDOS), Ctrl-R resumes the mission at
 * once, Ctrl-E extends the wait, Ctrl-F re-reads the mission's files. If nobody answers in time
 * the mission resumes, as at sea. Everything else typed meanwhile is ignored, as the glider does.
 */
final class SurfaceCountdown {
    static final int CTRL_C = 0x03;
    static final int CTRL_E = 0x05;
    static final int CTRL_F = 0x06;
    static final int CTRL_R = 0x12;
    private static final long TICK_NANOS = 10_000_000_000L;

    /** How the wait ended. */
    enum Answer {
        /** Ctrl-C: the pilot has the GliderDOS prompt. */
        CONTROL_C,
        /** Ctrl-R: resume the mission now. */
        RESUME,
        /** Nobody answered in time: the mission resumes. */
        NO_ANSWER
    }

    private SurfaceCountdown() {
    }

    /**
     * Waits {@code wait} for a key; Ctrl-E adds {@code extend}. Prints the keys first.
     *
     * @param dir the glider's files, whose {@code .ma} files Ctrl-F counts
     */
    static Answer run(ShellLink shell, Duration wait, Duration extend, Path dir) throws IOException {
        shell.say(SurfaceDialog.keys(extend.toSeconds()));
        long end = System.nanoTime() + wait.toNanos();
        long nextTick = System.nanoTime();
        byte[] buf = new byte[256];
        while (true) {
            long now = System.nanoTime();
            if (now - end >= 0) {
                shell.say("No answer: resuming the mission.\r\n");
                return Answer.NO_ANSWER;
            }
            if (now - nextTick >= 0) {
                shell.say(SurfaceDialog.countdown((end - now + 999_999_999L) / 1_000_000_000L));
                nextTick = now + TICK_NANOS;
            }
            long waitMillis = Math.max(1, Math.min(end - now, nextTick - now) / 1_000_000);
            int n = shell.read(buf, 0, buf.length, waitMillis);
            for (int i = 0; i < n; i++) {
                switch (buf[i]) {
                    case CTRL_C -> {
                        // what follows the key (a command typed ahead) is for GliderDOS
                        shell.unread(buf, i + 1, n - i - 1);
                        shell.say("^C\r\nMission stopped by the operator: GliderDOS\r\n");
                        return Answer.CONTROL_C;
                    }
                    case CTRL_R -> {
                        shell.say("^R\r\nResuming the mission.\r\n");
                        return Answer.RESUME;
                    }
                    case CTRL_E -> {
                        end += extend.toNanos();
                        shell.say("^E\r\nSurface time extended by " + extend.toSeconds() + " s\r\n");
                        nextTick = System.nanoTime();
                    }
                    case CTRL_F -> shell.say("^F\r\nRe-read the mafiles: " + mafiles(dir) + " file(s)\r\n");
                    default -> { }
                }
            }
        }
    }

    private static long mafiles(Path dir) throws IOException {
        try (var list = Files.list(dir)) {
            return list.filter(p -> p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".ma")).count();
        }
    }
}
