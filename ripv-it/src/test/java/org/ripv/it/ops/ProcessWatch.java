package org.ripv.it.ops;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.UUID;

/**
 * Finds the processes a test started, however deep: each carries an environment variable with a
 * value unique to this watch, and every descendant inherits it. Linux only (/proc).
 */
final class ProcessWatch {
    static final String VARIABLE = "RIPV_TEST_PROCESS_MARK";
    final String mark = UUID.randomUUID().toString();

    static boolean supported() {
        return Files.isReadable(Path.of("/proc/self/environ")) && Files.isReadable(Path.of("/proc/net/tcp"));
    }

    /** The live processes carrying the mark, as "pid cmdline". */
    Set<String> processes() {
        Set<String> found = new LinkedHashSet<>();
        for (Path p : procs()) {
            try {
                byte[] env = Files.readAllBytes(p.resolve("environ"));
                if (new String(env, StandardCharsets.UTF_8).contains(VARIABLE + "=" + mark)) {
                    String cmd = new String(Files.readAllBytes(p.resolve("cmdline")), StandardCharsets.UTF_8).replace('\0', ' ');
                    found.add(p.getFileName() + " " + cmd.strip());
                }
            } catch (IOException | SecurityException e) {
                // gone, or not ours to read
            }
        }
        return found;
    }

    /** Listening TCP sockets owned by a marked process, as "pid inode". */
    Set<String> listening() {
        Set<String> inodes = listeningInodes();
        Set<String> found = new LinkedHashSet<>();
        if (inodes.isEmpty()) {
            return found;
        }
        for (String proc : processes()) {
            String pid = proc.substring(0, proc.indexOf(' '));
            try (DirectoryStream<Path> fds = Files.newDirectoryStream(Path.of("/proc", pid, "fd"))) {
                for (Path fd : fds) {
                    try {
                        String link = Files.readSymbolicLink(fd).toString();
                        if (link.startsWith("socket:[")) {
                            String inode = link.substring(8, link.length() - 1);
                            if (inodes.contains(inode)) {
                                found.add(proc + " (socket " + inode + ")");
                            }
                        }
                    } catch (IOException e) {
                        // closed meanwhile
                    }
                }
            } catch (IOException e) {
                // exited meanwhile
            }
        }
        return found;
    }

    private static Set<String> listeningInodes() {
        Set<String> inodes = new HashSet<>();
        for (String table : List.of("/proc/net/tcp", "/proc/net/tcp6")) {
            try {
                for (String line : Files.readAllLines(Path.of(table))) {
                    String[] f = line.strip().split("\\s+");
                    if (f.length > 9 && f[3].equals("0A")) { // TCP_LISTEN
                        inodes.add(f[9]);
                    }
                }
            } catch (IOException e) {
                // no IPv6
            }
        }
        return inodes;
    }

    private static List<Path> procs() {
        try (var s = Files.list(Path.of("/proc"))) {
            return s.filter(p -> p.getFileName().toString().chars().allMatch(Character::isDigit)).toList();
        } catch (IOException e) {
            return List.of();
        }
    }
}
