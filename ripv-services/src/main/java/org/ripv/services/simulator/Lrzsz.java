package org.ripv.services.simulator;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated glider's {@code zs} and {@code zr}: lrzsz's {@code sz} and {@code rz} run as
 * child processes in the glider's directory, their standard input and output wired to the link,
 * as a glider's own ZMODEM would talk on its modem line. lrzsz restricts {@code rz} to its
 * directory and does its own timeouts, retries, CRC-32 and crash recovery (an offset asked for
 * by the receiver), so the shore side meets a real, independent ZMODEM.
 */
final class Lrzsz {
    private static final Logger log = LoggerFactory.getLogger(Lrzsz.class);

    private Lrzsz() {
    }

    /** Sends {@code files} (names in {@code dir}); returns what to print afterwards. */
    static String send(ShellLink shell, Path dir, List<String> names) throws IOException {
        List<String> cmd = new ArrayList<>(List.of("sz", "-b", "-q"));
        cmd.addAll(names);
        int code = run(shell, dir, cmd);
        return code == 0 ? names.size() + " file(s) sent" : "ZMODEM send failed (sz exit " + code + ")";
    }

    /** Receives files into {@code dir}, replacing files of the same name. */
    static String receive(ShellLink shell, Path dir) throws IOException {
        int code = run(shell, dir, List.of("rz", "-b", "-q", "-y"));
        return code == 0 ? "file(s) received" : "ZMODEM receive failed (rz exit " + code + ")";
    }

    private static int run(ShellLink shell, Path dir, List<String> cmd) throws IOException {
        Process p;
        try {
            p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        } catch (IOException e) {
            throw new IOException("cannot run " + cmd.get(0) + " (is lrzsz installed?): " + e.getMessage(), e);
        }
        Thread toLink = new Thread(() -> copy(p.getInputStream(), shell), "glider-simulator-" + cmd.get(0));
        toLink.setDaemon(true);
        toLink.start();
        OutputStream toProcess = p.getOutputStream();
        byte[] buf = new byte[8192];
        try {
            // the link's bytes go to the process for as long as it runs; reads time out so its end is seen
            while (p.isAlive()) {
                int n = shell.read(buf, 0, buf.length, 200);
                if (n > 0) {
                    try {
                        toProcess.write(buf, 0, n);
                        toProcess.flush();
                    } catch (IOException ended) {
                        keepForTheShell(shell, buf, n);
                        break;
                    }
                }
            }
            if (!p.waitFor(10, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
            toLink.join(10_000);
            return p.exitValue();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            p.destroyForcibly();
            return -1;
        } catch (IOException e) {
            p.destroyForcibly(); // the call dropped: the glider's lrzsz gives up too
            throw e;
        } finally {
            try {
                toProcess.close();
            } catch (IOException ignored) {
                // the process is gone
            }
        }
    }

    /** Bytes read after the process ended go back to the shell, but not ZMODEM's closing "OO". */
    private static void keepForTheShell(ShellLink shell, byte[] buf, int n) {
        int from = 0;
        while (from < n && from < 2 && buf[from] == 'O') {
            from++;
        }
        if (from < n) {
            shell.unread(buf, from, n - from);
        }
    }

    private static void copy(InputStream in, ShellLink shell) {
        byte[] buf = new byte[8192];
        try {
            for (int n; (n = in.read(buf)) > 0; ) {
                shell.write(buf, 0, n);
                shell.flush();
            }
        } catch (IOException e) {
            log.debug("lrzsz output to the link ended: {}", e.toString());
        }
    }
}
