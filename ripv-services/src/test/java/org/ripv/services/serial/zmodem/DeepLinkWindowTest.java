package org.ripv.services.serial.zmodem;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.bench.YmodemBaudRelay;
import org.ripv.services.serial.Socat;
import org.ripv.services.serial.TcpLink;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.testing.Tools;

/**
 * A vehicle on a TCP link (an Iridium call through a RUDICS gateway, a terminal server): the
 * socket takes the whole file at once while the modem behind it needs seconds, so a sender that
 * streams it all then waits for the answer to ZEOF longer than a frame may take. RIPV's sender
 * keeps a window on such a link (ZCRCQ, the receiver's ZACKs), here against lrzsz's rz behind a
 * relay paced like a 115,200-baud line, with a frame timeout far shorter than the file's time on
 * the line.
 */
class DeepLinkWindowTest {
    private static final long FRAME_TIMEOUT_MILLIS = 1000;
    @TempDir
    Path tmp;

    @BeforeAll
    static void tools() {
        Tools.require("socat", "rz");
    }

    @Test
    void aFileLongerOnTheLineThanAFrameTimeoutArrivesWhole() throws Exception {
        Path file = LrzszZmodemTest.sampleFiles(tmp.resolve("src"), 96 * 1024).get(0); // 8.5 s at 11,520 bytes/s
        Path out = Files.createDirectories(tmp.resolve("rz-out"));
        try (Rz rz = new Rz(out); TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + rz.relay.port(), 5000)) {
            assertThat(link.buffersDeeply()).isTrue();
            assertThat(new ZmodemSender(link, FRAME_TIMEOUT_MILLIS, null).send(SendFile.of(file))).isZero();
            assertThat(rz.socat.waitFor(Duration.ofSeconds(20))).as(rz.socat.log()).isZero();
        }
        assertThat(Files.readAllBytes(out.resolve(file.getFileName().toString()))).isEqualTo(Files.readAllBytes(file));
    }

    /** Why the window: without it the same transfer gives up at the end of the file. */
    @Test
    void withoutTheWindowTheEndOfTheFileIsNotAnsweredInTime() throws Exception {
        Path file = LrzszZmodemTest.sampleFiles(tmp.resolve("src"), 96 * 1024).get(0);
        Path out = Files.createDirectories(tmp.resolve("rz-out"));
        try (Rz rz = new Rz(out); TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + rz.relay.port(), 5000)) {
            ZmodemSender sender = new ZmodemSender(link, FRAME_TIMEOUT_MILLIS, null).window(0);
            assertThatThrownBy(() -> sender.send(SendFile.of(file))).isInstanceOf(ZmodemException.class)
                    .hasMessageContaining("did not answer the end of");
        }
    }

    @Test
    void aWindowTooSmallToQueryIsRefused() throws Exception {
        try (ServerSocket s = new ServerSocket(0); TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + s.getLocalPort(), 5000)) {
            assertThatThrownBy(() -> new ZmodemSender(link, 1000, null).window(100)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("at least 256 bytes");
        }
    }

    /** lrzsz's rz behind socat, reached through a relay paced like the line. */
    private static final class Rz implements AutoCloseable {
        final Socat socat;
        final YmodemBaudRelay relay;

        Rz(Path out) throws Exception {
            int port;
            try (ServerSocket s = new ServerSocket(0)) {
                port = s.getLocalPort();
            }
            socat = Socat.start(out, "TCP-LISTEN:" + port + ",bind=127.0.0.1,reuseaddr", "SYSTEM:'exec rz -q -y'");
            relay = new YmodemBaudRelay(115_200, new InetSocketAddress("127.0.0.1", port));
        }

        @Override
        public void close() throws Exception {
            relay.close();
            socat.close();
        }
    }
}
