package org.ripv.services.serial.zmodem;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.EOFException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialLink;
import org.ripv.services.serial.Socat;
import org.ripv.services.serial.ymodem.ByteLink;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.testing.Tools;

/**
 * Our ZMODEM against lrzsz's {@code sz}/{@code rz} through a socat pseudo-terminal, both ways,
 * and crash recovery: a call cut at 40 % is continued by the next {@code sz} from the part's
 * length, byte-identical.
 */
class LrzszZmodemTest {
    @TempDir
    Path tmp;

    @BeforeAll
    static void tools() {
        Tools.require("socat", "sz", "rz");
    }

    /** Sizes that probe the edges, with every byte ZMODEM must escape sprinkled in. */
    static List<Path> sampleFiles(Path dir, int... sizes) throws IOException {
        Files.createDirectories(dir);
        Random r = new Random(11);
        List<Path> files = new ArrayList<>();
        for (int i = 0; i < sizes.length; i++) {
            byte[] b = new byte[sizes[i]];
            r.nextBytes(b);
            for (int j = 0; j < b.length; j += 89) {
                b[j] = (byte) new int[] {0x18, 0x10, 0x11, 0x13, 0x90, 0x91, 0x93, 0x7F, 0xFF, 0x0D, 0x2A}[j % 11];
            }
            Path p = dir.resolve("file" + i + ".bin");
            Files.write(p, b);
            files.add(p);
        }
        return files;
    }

    @Test
    void ourReceiverAgainstSz() throws Exception {
        Path src = tmp.resolve("src");
        List<Path> files = sampleFiles(src, 0, 1, 1024, 5000, 300_000);
        StringBuilder names = new StringBuilder();
        files.forEach(f -> names.append(' ').append(f.getFileName()));
        Path pty = tmp.resolve("ttySZ");
        Path out = Files.createDirectories(tmp.resolve("out"));
        try (Socat socat = Socat.start(src, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec sz -q" + names + "'", pty);
             SerialLink link = SerialLink.open(LinkSettings.defaults(pty.toString()))) {
            List<ZmodemReceiver.Received> got = new ZmodemReceiver(link, 5000, null)
                    .receive(new ResumeStore(tmp.resolve("parts")), out);
            assertEquals(files.size(), got.size());
            for (Path f : files) {
                assertArrayEquals(Files.readAllBytes(f), Files.readAllBytes(out.resolve(f.getFileName().toString())),
                        f.getFileName().toString());
            }
            assertEquals(0, socat.waitFor(Duration.ofSeconds(20)), socat.log());
        }
    }

    @Test
    void ourSenderAgainstRz() throws Exception {
        Path src = tmp.resolve("src");
        List<Path> files = sampleFiles(src, 0, 3000, 200_000);
        for (Path f : files) {
            Path out = Files.createDirectories(tmp.resolve("rz-out-" + f.getFileName()));
            Path pty = tmp.resolve("ttyRZ-" + f.getFileName());
            try (Socat socat = Socat.start(out, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec rz -q -y'", pty)) {
                try (SerialLink link = SerialLink.open(LinkSettings.defaults(pty.toString()))) {
                    assertEquals(0, new ZmodemSender(link, 5000, null).send(SendFile.of(f)));
                }
                assertEquals(0, socat.waitFor(Duration.ofSeconds(20)), socat.log());
            }
            assertArrayEquals(Files.readAllBytes(f), Files.readAllBytes(out.resolve(f.getFileName().toString())));
        }
    }

    /**
     * rz that cannot write the file skips it: our sender reports the skip and ends the session, so
     * rz exits at once (before, it waited out its own timeouts, about two and a half minutes of a
     * call at the surface, as ToVehicleEndToEndTest's glider did).
     */
    @Test
    void aSkippedFileEndsTheReceiversSessionAtOnce() throws Exception {
        Path src = tmp.resolve("src");
        Path f = sampleFiles(src, 3000).get(0);
        Path out = Files.createDirectories(tmp.resolve("rz-blocked"));
        Files.createDirectories(out.resolve(f.getFileName().toString())); // a folder in the way
        Path pty = tmp.resolve("ttyRZ-skip");
        try (Socat socat = Socat.start(out, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec rz -q -y'", pty)) {
            try (SerialLink link = SerialLink.open(LinkSettings.defaults(pty.toString()))) {
                ZmodemException e = assertThrows(ZmodemException.class, () -> new ZmodemSender(link, 5000, null).send(SendFile.of(f)));
                assertTrue(e.getMessage().contains("skipped"), e.getMessage());
                socat.waitFor(Duration.ofSeconds(20)); // the line still open: rz ends because the session did
            }
        }
    }

    /** The call drops once 40 % of the file has come; the next sz is asked from the part's length. */
    @Test
    void aCallCutAt40PercentIsResumedByTheNextCall() throws Exception {
        Path src = tmp.resolve("src");
        Path file = sampleFiles(src, 120_000).get(0);
        ResumeStore store = new ResumeStore(tmp.resolve("parts"));
        Path out = Files.createDirectories(tmp.resolve("out"));
        Path pty = tmp.resolve("ttyCUT");
        try (Socat socat = Socat.start(src, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec sz -q file0.bin'", pty);
             SerialLink link = SerialLink.open(LinkSettings.defaults(pty.toString()))) {
            ByteLink cut = new CutLink(link, 48_000);
            assertThrows(EOFException.class, () -> new ZmodemReceiver(cut, 3000, null).receive(store, out));
        }
        long part = store.partLength("file0.bin");
        assertTrue(part > 20_000 && part <= 48_000, "kept a part of " + part + " bytes");
        assertFalse(Files.exists(out.resolve("file0.bin")), "a cut file is never shown as complete");
        try (Socat socat = Socat.start(src, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec sz -q file0.bin'", pty);
             SerialLink link = SerialLink.open(LinkSettings.defaults(pty.toString()))) {
            List<ZmodemReceiver.Received> got = new ZmodemReceiver(link, 5000, null).receive(store, out);
            assertEquals(1, got.size());
            assertEquals(part, got.get(0).resumedAt());
            assertTrue(got.get(0).note().contains("resumed at byte " + part) && got.get(0).note().contains("a call at"),
                    got.get(0).note());
            assertEquals(0, socat.waitFor(Duration.ofSeconds(20)), socat.log());
        }
        assertArrayEquals(Files.readAllBytes(file), Files.readAllBytes(out.resolve("file0.bin")));
        assertEquals(-1, store.partLength("file0.bin"));
    }

    /** A file that changed on the vehicle between calls is fetched whole, never spliced onto the old part. */
    @Test
    void aFileChangedBetweenCallsIsFetchedWhole() throws Exception {
        Path src = tmp.resolve("src");
        Path file = sampleFiles(src, 60_000).get(0);
        ResumeStore store = new ResumeStore(tmp.resolve("parts"));
        Path out = Files.createDirectories(tmp.resolve("out"));
        Path pty = tmp.resolve("ttyCHG");
        try (Socat socat = Socat.start(src, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec sz -q file0.bin'", pty);
             SerialLink link = SerialLink.open(LinkSettings.defaults(pty.toString()))) {
            assertThrows(EOFException.class, () -> new ZmodemReceiver(new CutLink(link, 30_000), 3000, null).receive(store, out));
        }
        assertTrue(store.partLength("file0.bin") > 0);
        byte[] changed = Files.readAllBytes(file);
        changed[0] ^= 1;
        Files.write(file, changed);
        Files.setLastModifiedTime(file, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis() + 5000));
        try (Socat socat = Socat.start(src, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec sz -q file0.bin'", pty);
             SerialLink link = SerialLink.open(LinkSettings.defaults(pty.toString()))) {
            List<ZmodemReceiver.Received> got = new ZmodemReceiver(link, 5000, null).receive(store, out);
            assertEquals(0, got.get(0).resumedAt());
            assertTrue(got.get(0).note().contains("changed on the vehicle"), got.get(0).note());
        }
        assertArrayEquals(changed, Files.readAllBytes(out.resolve("file0.bin")));
    }

    /** A link that hangs up after a number of bytes, as a dropped Iridium call does. */
    static final class CutLink implements ByteLink {
        private final ByteLink link;
        private long left;

        CutLink(ByteLink link, long bytes) {
            this.link = link;
            this.left = bytes;
        }

        @Override
        public int read(byte[] b, int off, int len, long timeoutMillis) throws IOException {
            if (left <= 0) {
                throw new EOFException("the call dropped");
            }
            int n = link.read(b, off, (int) Math.min(len, left), timeoutMillis);
            left -= n;
            return n;
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            if (left <= 0) {
                throw new EOFException("the call dropped");
            }
            link.write(b, off, len);
        }

        @Override
        public void flush() throws IOException {
            link.flush();
        }
    }
}
