package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.testing.Tools;
import org.ripv.services.serial.ymodem.DirectorySink;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.serial.ymodem.YmodemReceiver;
import org.ripv.services.serial.ymodem.YmodemSender;

/**
 * Our YMODEM against lrzsz through a socat pseudo-terminal, opened with jSerialComm. lrzsz runs
 * on pipes behind socat (on a Linux pty its exit discards its own last byte).
 */
class LrzszInteropTest {
    @TempDir
    Path tmp;

    @BeforeAll
    static void tools() {
        Tools.require("socat", "sb", "rb");
    }

    /** Files that probe the edges: empty, exact block multiples, a short tail, control bytes, 1 MB. */
    private List<Path> sampleFiles(Path dir) throws Exception {
        Files.createDirectories(dir);
        Random r = new Random(7);
        List<Path> files = new ArrayList<>();
        int[] sizes = {0, 128, 1024, 3 * 1024 + 100, 1024 * 1024 + 1};
        for (int i = 0; i < sizes.length; i++) {
            byte[] b = new byte[sizes[i]];
            r.nextBytes(b);
            for (int j = 0; j < b.length; j += 97) {
                b[j] = (byte) new int[] {0x18, 0x1A, 0x00, 0xFF, 0x11, 0x13}[j % 6];
            }
            Path p = dir.resolve("file" + i + ".bin");
            Files.write(p, b);
            files.add(p);
        }
        Path text = dir.resolve("mission.log");
        Files.writeString(text, "time depth\r\n1 2\r\n".repeat(500));
        files.add(text);
        return files;
    }

    static String sha256(Path p) throws Exception {
        return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(p)));
    }

    @Test
    void ourReceiverAgainstSb() throws Exception {
        Path src = tmp.resolve("src");
        List<Path> files = sampleFiles(src);
        Path pty = tmp.resolve("ttySB");
        StringBuilder names = new StringBuilder();
        files.forEach(f -> names.append(' ').append(f.getFileName()));
        try (Socat socat = Socat.start(src, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec sb --ymodem -k -q" + names + "'",
                pty);
             SerialLink link = SerialLink.open(LinkSettings.defaults(pty.toString()))) {
            Path out = tmp.resolve("out");
            List<FileHeader> got = new YmodemReceiver(link, YmodemConfig.lrzsz(), null).receiveBatch(new DirectorySink(out));
            assertEquals(files.size(), got.size());
            for (Path f : files) {
                assertEquals(sha256(f), sha256(out.resolve(f.getFileName().toString())), f.getFileName().toString());
            }
            assertEquals(0, socat.waitFor(Duration.ofSeconds(20)), socat.log());
        }
    }

    @Test
    void ourSenderAgainstRb() throws Exception {
        Path src = tmp.resolve("src");
        List<Path> files = sampleFiles(src);
        Path out = Files.createDirectories(tmp.resolve("rb-out"));
        Path pty = tmp.resolve("ttyRB");
        try (Socat socat = Socat.start(out, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec rb --ymodem -y -q'", pty)) {
            try (SerialLink link = SerialLink.open(LinkSettings.defaults(pty.toString()))) {
                List<SendFile> sends = new ArrayList<>();
                for (Path f : files) {
                    sends.add(SendFile.of(f));
                }
                new YmodemSender(link, YmodemConfig.lrzsz(), null).sendBatch(sends);
            }
            assertEquals(0, socat.waitFor(Duration.ofSeconds(20)), socat.log());
            for (Path f : files) {
                assertEquals(sha256(f), sha256(out.resolve(f.getFileName().toString())), f.getFileName().toString());
            }
        }
    }
}
