package org.ripv.services.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;

/**
 * The relay stands for a serial line: however its bytes come (all at once here, so it catches up
 * after any pause of its own), they never reach the far end faster than the line's rate, and they
 * arrive whole and in order.
 */
class YmodemBaudRelayTest {
    @Test
    void neverFasterThanTheLineAndNothingLost() throws Exception {
        byte[] data = new byte[23_040]; // two seconds at 115,200 baud
        new Random(7).nextBytes(data);
        try (ServerSocket far = new ServerSocket(0);
             YmodemBaudRelay relay = new YmodemBaudRelay(115_200, new InetSocketAddress("127.0.0.1", far.getLocalPort()))) {
            CompletableFuture<byte[]> received = CompletableFuture.supplyAsync(() -> {
                try (Socket s = far.accept(); InputStream in = s.getInputStream()) {
                    return in.readNBytes(data.length);
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            try (Socket near = new Socket("127.0.0.1", relay.port())) {
                long start = System.nanoTime();
                near.getOutputStream().write(data);
                byte[] got = received.get();
                double seconds = (System.nanoTime() - start) / 1e9;
                assertThat(Arrays.equals(got, data)).as("the bytes, whole and in order").isTrue();
                assertThat(seconds).as("23,040 bytes at 11,520 bytes/s").isGreaterThanOrEqualTo(1.95);
            }
        }
    }
}
