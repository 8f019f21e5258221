package org.ripv.services.serial.zmodem;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.EOFException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.SendFile;

/**
 * A ZMODEM peer that lies or breaks: sizes and offsets that do not add up, a call that drops in
 * a header, garbage instead of frames. Each is a clear error, and nothing it sent is kept as if
 * it were complete (nor, when it lied, as a part to resume).
 */
class ZmodemFaultsTest {
    static final long MTIME = 1_764_000_000L;

    @TempDir
    Path tmp;

    private ResumeStore store() throws Exception {
        return new ResumeStore(tmp.resolve("parts"));
    }

    private Path out() throws Exception {
        return Files.createDirectories(tmp.resolve("out"));
    }

    private static byte[] random(int n) {
        byte[] b = new byte[n];
        new Random(n).nextBytes(b);
        return b;
    }

    @Test
    void aPeerSendingMoreThanItAnnouncedLosesThePart() throws Exception {
        byte[] s = new Script().hex(Zmodem.ZRQINIT, 0).zfile("A.DBD", 100, MTIME).bin32(Zmodem.ZDATA, 0)
                .data(random(200), Zmodem.ZCRCE).hex(Zmodem.ZEOF, 200).bytes();
        ResumeStore store = store();
        ZmodemException e = assertThrows(ZmodemException.class,
                () -> new ZmodemReceiver(Script.playing(s), 200, null).receive(store, out()));
        assertEquals(ZmodemException.Kind.PROTOCOL, e.kind());
        assertTrue(e.getMessage().contains("more of A.DBD than the 100 bytes it announced"), e.getMessage());
        assertEquals(-1, store.partLength("A.DBD"));
        assertFalse(Files.exists(tmp.resolve("out/A.DBD")));
    }

    @Test
    void aZeofThatDisagreesWithTheAnnouncedSizeIsAnError() throws Exception {
        byte[] s = new Script().hex(Zmodem.ZRQINIT, 0).zfile("B.DBD", 300, MTIME).bin32(Zmodem.ZDATA, 0)
                .data(random(200), Zmodem.ZCRCE).hex(Zmodem.ZEOF, 200).bytes();
        ResumeStore store = store();
        ZmodemException e = assertThrows(ZmodemException.class,
                () -> new ZmodemReceiver(Script.playing(s), 200, null).receive(store, out()));
        assertTrue(e.getMessage().contains("announced B.DBD as 300 bytes but ended it at 200"), e.getMessage());
        assertEquals(-1, store.partLength("B.DBD"));
        assertFalse(Files.exists(tmp.resolve("out/B.DBD")));
    }

    @Test
    void aPeerThatKeepsSendingFromTheWrongOffsetIsNotBelieved() throws Exception {
        Script sc = new Script().hex(Zmodem.ZRQINIT, 0).zfile("C.DBD", 5000, MTIME);
        for (int i = 0; i < 12; i++) {
            sc.bin32(Zmodem.ZDATA, 4000).data(random(100), Zmodem.ZCRCE);
        }
        ZmodemException e = assertThrows(ZmodemException.class,
                () -> new ZmodemReceiver(Script.playing(sc.bytes()), 200, null).receive(store(), out()));
        assertTrue(e.getMessage().contains("from byte 4000 when asked for byte 0"), e.getMessage());
    }

    @Test
    void aCallDroppedDuringTheZfileHeaderKeepsNothing() throws Exception {
        byte[] whole = new Script().hex(Zmodem.ZRQINIT, 0).zfile("D.DBD", 1000, MTIME).bytes();
        byte[] cut = Arrays.copyOf(whole, whole.length - 20); // inside ZFILE's subpacket
        ResumeStore store = store();
        assertThrows(EOFException.class, () -> new ZmodemReceiver(Script.playing(cut), 200, null).receive(store, out()));
        assertEquals(-1, store.partLength("D.DBD"));
        try (var files = Files.list(out())) {
            assertEquals(0, files.count());
        }
    }

    @Test
    void garbageInsteadOfFramesIsAClearErrorNotAnEndlessWait() throws Exception {
        byte[] noise = random(20_000);
        for (int i = 0; i < noise.length; i++) {
            if (noise[i] == '*' || noise[i] == 0x18) {
                noise[i] = 'x';
            }
        }
        ZmodemException e = assertThrows(ZmodemException.class,
                () -> new ZmodemReceiver(Script.playing(noise), 200, null).receive(store(), out()));
        assertEquals(ZmodemException.Kind.PROTOCOL, e.kind());
        assertTrue(e.getMessage().contains("bytes of garbage where ZMODEM frames were expected"), e.getMessage());
    }

    @Test
    void aReceiverAskingToResumeBeyondTheFileIsRefused() throws Exception {
        byte[] s = new Script().hex(Zmodem.ZRINIT, 0).hex(Zmodem.ZRPOS, 5000).bytes();
        ZmodemException e = assertThrows(ZmodemException.class,
                () -> new ZmodemSender(Script.playing(s), 200, null).send(SendFile.of("E.BIN", random(1000))));
        assertTrue(e.getMessage().contains("asked to resume E.BIN at byte 5000, beyond its 1000 bytes"), e.getMessage());
    }

    @Test
    void aPartLongerThanTheFileOrFromAnotherVersionIsNotResumed() throws Exception {
        ResumeStore store = store();
        FileHeader v1 = new FileHeader("F.DBD", 1000, MTIME, 0);
        try (var o = store.open(v1, 0)) {
            o.write(random(600));
        }
        store.interrupted("F.DBD", 0, 600);
        assertEquals(600, store.offer(v1).offset());
        ResumeStore.Start shorter = store.offer(new FileHeader("F.DBD", 500, MTIME, 0));
        assertEquals(0, shorter.offset());
        assertTrue(shorter.note().contains("changed on the vehicle"), shorter.note());
        assertEquals(-1, store.partLength("F.DBD"));

        try (var o = store.open(v1, 0)) {
            o.write(random(600));
        }
        ResumeStore.Start newer = store.offer(new FileHeader("F.DBD", 1000, MTIME + 60, 0));
        assertEquals(0, newer.offset());
        assertTrue(newer.note().contains("fetched whole"), newer.note());
    }
}
