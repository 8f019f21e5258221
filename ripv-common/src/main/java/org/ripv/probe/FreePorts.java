package org.ripv.probe;

import java.io.IOException;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Ports to give a process about to be launched (a benchmark's server, a test's services): free
 * when asked for, and likely to stay free until that process binds them.
 *
 * <p>A port the kernel hands out for port 0 comes from its ephemeral range, the same range every
 * outgoing connection on the machine draws from: between the check and the launched process's
 * bind, a connection elsewhere can take it ("Address already in use"). These ports are chosen
 * below that range, where the kernel hands out nothing by itself, walking up from a random start
 * so that two JVMs asking at once are unlikely to meet. Where the range leaves no room below it,
 * they fall back to port 0.
 */
public final class FreePorts {
    private static final int LOWEST = 10_000;
    private static final int ROOM = 2_000;
    private static final Path EPHEMERAL = Path.of("/proc/sys/net/ipv4/ip_local_port_range");

    private static final int CEILING = ephemeralStart();
    private static final boolean ROOM_BELOW = CEILING - LOWEST >= ROOM;
    private static final AtomicInteger NEXT = new AtomicInteger(
            ROOM_BELOW ? LOWEST + ThreadLocalRandom.current().nextInt(CEILING - LOWEST) : 0);

    private FreePorts() {}

    /** One free port. */
    public static int one() throws IOException {
        if (!ROOM_BELOW) {
            return kernelsChoice();
        }
        for (int tried = 0; tried < CEILING - LOWEST; tried++) {
            int port = NEXT.getAndUpdate(p -> p + 1 >= CEILING ? LOWEST : p + 1);
            if (bindable(port)) {
                return port;
            }
        }
        return kernelsChoice();
    }

    /** {@code n} different free ports. */
    public static int[] several(int n) throws IOException {
        int[] ports = new int[n];
        for (int i = 0; i < n; i++) {
            ports[i] = one();
        }
        return ports;
    }

    private static boolean bindable(int port) {
        try (ServerSocket s = new ServerSocket(port)) {
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    private static int kernelsChoice() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    /** The lowest port the kernel gives out by itself (Linux's default where it cannot be read). */
    static int ephemeralStart() {
        try {
            return Integer.parseInt(Files.readString(EPHEMERAL).trim().split("\\s+")[0]);
        } catch (IOException | RuntimeException e) {
            return 32_768;
        }
    }
}
