package org.ripv.services.serial.zmodem;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.EOFException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.Size;

/**
 * Fuzzing the ZMODEM frame decoder and the receiver built on it: whatever a vehicle sends —
 * noise, ZDLE escapes cut anywhere, valid frames with bytes flipped, dropped or repeated —
 * decoding ends with a frame, a {@link ZmodemException}, a timeout or the link's end, never
 * another exception or a hang; and a file the receiver reports complete is exactly what was sent.
 */
class ZFrameReaderFuzzTest {
    static final long MTIME = 1_764_000_000L;

    @Property(tries = 300)
    void noiseNeverBreaksTheDecoder(@ForAll @Size(max = 3000) List<Byte> noise, @ForAll boolean crc32) {
        byte[] b = new byte[noise.size()];
        for (int i = 0; i < b.length; i++) {
            b[i] = noise.get(i);
        }
        ZFrameReader r = new ZFrameReader(Script.playing(b)).garbageLimit(1000);
        byte[] into = new byte[Zmodem.MAX_SUBPACKET];
        try {
            for (int i = 0; i < 100; i++) {
                r.header(50, null);
                ZFrameReader.Subpacket s = r.data(into, crc32, 50);
                assertThat(s.length()).isBetween(0, into.length);
            }
        } catch (ZmodemException | ZFrameReader.Timeout | EOFException expected) {
            // the only ways a decode may end
        } catch (IOException e) {
            throw new AssertionError("unexpected " + e, e);
        }
    }

    @Provide
    Arbitrary<int[]> damage() {
        return Arbitraries.integers().between(0, 7000).array(int[].class).ofMaxSize(6);
    }

    /** A whole session with a few bytes flipped, dropped or doubled. */
    @Property(tries = 150)
    void aDamagedSessionEndsCleanlyAndNeverDeliversWrongBytes(@ForAll("damage") int[] hits, @ForAll int mode)
            throws Exception {
        byte[] content = new byte[3000];
        new java.util.Random(5).nextBytes(content);
        Script sc = new Script().hex(Zmodem.ZRQINIT, 0).zfile("G.DBD", content.length, MTIME).bin32(Zmodem.ZDATA, 0);
        for (int off = 0; off < content.length; off += 1024) {
            int n = Math.min(1024, content.length - off);
            boolean last = off + n == content.length;
            sc.data(Arrays.copyOfRange(content, off, off + n), last ? Zmodem.ZCRCE : Zmodem.ZCRCG);
        }
        byte[] clean = sc.hex(Zmodem.ZEOF, content.length).hex(Zmodem.ZFIN, 0).raw("OO".getBytes()).bytes();
        byte[] s = clean.clone();
        for (int h : hits) {
            int at = h % s.length;
            switch (Math.floorMod(mode + h, 3)) {
                case 0 -> s[at] ^= (byte) (1 + (h & 0x7F));
                case 1 -> s = concat(Arrays.copyOf(s, at), Arrays.copyOfRange(s, Math.min(s.length, at + 1), s.length));
                default -> s = concat(Arrays.copyOf(s, at + 1), Arrays.copyOfRange(s, at, s.length));
            }
        }
        Path dir = Files.createTempDirectory("zfuzz");
        try {
            List<ZmodemReceiver.Received> got = new ZmodemReceiver(Script.playing(s), 30, null)
                    .receive(new ResumeStore(dir.resolve("parts")), Files.createDirectories(dir.resolve("out")));
            for (ZmodemReceiver.Received r : got) {
                assertThat(Files.readAllBytes(r.path())).isEqualTo(content);
            }
        } catch (ZmodemException | EOFException | ZFrameReader.Timeout expected) {
            // a damaged script that cannot be recovered from (the scripted peer never answers a ZRPOS)
        } finally {
            try (var walk = Files.walk(dir)) {
                walk.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] c = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return c;
    }
}
