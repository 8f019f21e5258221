package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.Attachment;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.FileData;
import org.ripv.testing.Tools;

/**
 * Issue 12's clean line, against a vehicle whose YMODEM is lrzsz (sb/rb behind a small shell,
 * {@code lrzsz-vehicle.sh}) on a socat pseudo-terminal: a {@code ymodem:get} followed by a
 * {@code ymodem:put}, again and again, on a machine the test loads with busy threads — the
 * conditions under which a late 'C' once turned the next {@code yr} into a refused {@code Cyr}. The
 * vehicle keeps a 'C' in its line after each send, as that late 'C' did, so the stray byte is there
 * in every round, not in 3 of 19.
 * And a vehicle that refuses the first start of each transfer: it is tried once more on a clean
 * line; and a get cancelled midway (CAN CAN to sb) leaves a clean line for the next put, as a
 * put cancelled midway (CAN CAN to rb) does for the next get.
 */
class LrzszCleanLineTest {
    static final Duration T = Duration.ofSeconds(60);
    static final int ROUNDS = 4;

    @TempDir
    Path tmp;

    @BeforeAll
    static void tools() {
        Tools.require("socat", "sb", "rb", "bash");
    }

    private Socat vehicle(Path dir, Path pty, String env) throws Exception {
        Path script = tmp.resolve("lrzsz-vehicle.sh");
        try (InputStream in = LrzszCleanLineTest.class.getResourceAsStream("lrzsz-vehicle.sh")) {
            Files.write(script, in.readAllBytes());
        }
        return Socat.start(dir, "pty,raw,echo=0,link=" + pty, "SYSTEM:'" + env + "exec bash " + script + " " + dir + "'", pty);
    }

    private static LinkSettings link(Path pty) {
        return LinkSettings.defaults(pty.toString()).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(200)).withYmodem(SimulatorOverTcpTest.YMODEM);
    }

    /** Threads that keep every core busy until closed (the machine the bug was seen on was loaded). */
    private static final class Load implements AutoCloseable {
        private final AtomicBoolean on = new AtomicBoolean(true);
        private final List<Thread> threads = new ArrayList<>();

        Load(int n) {
            for (int i = 0; i < n; i++) {
                Thread t = new Thread(() -> {
                    long x = 1;
                    while (on.get()) {
                        x = x * 6364136223846793005L + 1442695040888963407L;
                    }
                    if (x == 42) {
                        System.err.print(""); // keeps the loop from being optimised away
                    }
                }, "cpu-load-" + i);
                t.setDaemon(true);
                t.start();
                threads.add(t);
            }
        }

        @Override
        public void close() throws InterruptedException {
            on.set(false);
            for (Thread t : threads) {
                t.join();
            }
        }
    }

    @Test
    @SuppressWarnings("try")
    void getThenPutAgainAndAgainUnderLoadEveryTransferSucceeds() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("vehicle"));
        byte[] log = new byte[30_000];
        new Random(12).nextBytes(log);
        Files.write(dir.resolve("MISSION.LOG"), log);
        Path pty = tmp.resolve("ttyLZ");
        try (Socat socat = vehicle(dir, pty, "STRAY=1 ");
             Load load = new Load(2 * Runtime.getRuntime().availableProcessors())) {
            SerialPortServer serial = new SerialPortServer("testhost", List.of(link(pty)), null, false, tmp.resolve("work"));
            serial.start();
            try {
                ServiceProbe probe = new ServiceProbe(serial);
                Eventually.await("pty open", Duration.ofSeconds(10), () -> probe.status("ttyLZ").available());
                for (int round = 1; round <= ROUNDS; round++) {
                    ServiceProbe.Answer got = probe.send("ttyLZ", "ymodem:get MISSION.LOG", T);
                    assertTrue(got.ok(), "round " + round + " get: " + got.text() + "; socat: " + socat.log());
                    assertArrayEquals(log, assertInstanceOf(FileData.class, got.last().footer().result()).data());

                    byte[] up = new byte[8_000 + round * 1000];
                    new Random(round).nextBytes(up);
                    String name = "UP" + round + ".BIN";
                    ServiceProbe.Answer put = probe.send("ttyLZ", "ymodem:put " + name, new Attachment(name, up), T);
                    assertTrue(put.ok(), "round " + round + " put after a get: " + put.text());
                    assertArrayEquals(up, Files.readAllBytes(dir.resolve(name)));
                }
                // the line was clean before every put: none had to be tried again
                assertEquals(List.of(), probe.console("ttyLZ", ConsoleEntry.Kind.TRANSFER).stream().map(ConsoleEntry::text)
                        .filter(t -> t.contains("was refused")).toList());
                ServiceProbe.Answer listing = probe.send("ttyLZ", "dir", T);
                assertTrue(listing.ok(), listing.text());
                assertTrue(listing.text().contains("UP" + ROUNDS + ".BIN"), listing.text());
                assertTrue(!listing.text().contains("Bad command"), "the listing comes clean: " + listing.text());
            } finally {
                serial.stop();
            }
        }
    }

    /** Sends a transfer and cancels it at its first progress report; the answer must be CANCELLED. */
    private static void cancelledAtFirstProgress(ServiceProbe probe, String handle, String command,
                                                 Attachment attachment) throws Exception {
        AtomicBoolean asked = new AtomicBoolean();
        probe.onProgress = m -> {
            if (asked.compareAndSet(false, true)) {
                assertTrue(probe.cancel(handle, m.header().messageId()), "the transfer takes the cancel");
            }
        };
        ServiceProbe.Answer a = attachment == null ? probe.send(handle, command, T) : probe.send(handle, command, attachment, T);
        probe.onProgress = m -> { };
        assertTrue(asked.get(), "a progress came");
        assertEquals(org.ripv.messages.ErrorCode.CANCELLED, a.last().footer().errorCode(), a.text());
    }

    @Test
    @SuppressWarnings("try")
    void aGetCancelledMidwayLeavesACleanLineForTheNextPut() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("vehicle"));
        byte[] huge = new byte[3_000_000];
        new Random(15).nextBytes(huge);
        Files.write(dir.resolve("HUGE.LOG"), huge);
        Path pty = tmp.resolve("ttyCX");
        try (Socat socat = vehicle(dir, pty, "")) {
            SerialPortServer serial = new SerialPortServer("testhost", List.of(link(pty)), null, false, tmp.resolve("work"));
            serial.start();
            try {
                ServiceProbe probe = new ServiceProbe(serial);
                Eventually.await("pty open", Duration.ofSeconds(10), () -> probe.status("ttyCX").available());
                cancelledAtFirstProgress(probe, "ttyCX", "ymodem:get HUGE.LOG", null);
                byte[] up = new byte[5_000];
                new Random(16).nextBytes(up);
                ServiceProbe.Answer put = probe.send("ttyCX", "ymodem:put AFTER.BIN", new Attachment("AFTER.BIN", up), T);
                assertTrue(put.ok(), "the put after a cancelled get: " + put.text());
                assertArrayEquals(up, Files.readAllBytes(dir.resolve("AFTER.BIN")));
                ServiceProbe.Answer listing = probe.send("ttyCX", "dir", T);
                assertTrue(listing.ok() && listing.text().contains("AFTER.BIN") && !listing.text().contains("Bad command"),
                        listing.text());
            } finally {
                serial.stop();
            }
        }
    }

    @Test
    @SuppressWarnings("try")
    void aPutCancelledMidwayStopsRbAndLeavesACleanLineForTheNextGet() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("vehicle"));
        byte[] log = new byte[20_000];
        new Random(17).nextBytes(log);
        Files.write(dir.resolve("MISSION.LOG"), log);
        Path pty = tmp.resolve("ttyCP");
        try (Socat socat = vehicle(dir, pty, "")) {
            SerialPortServer serial = new SerialPortServer("testhost", List.of(link(pty)), null, false, tmp.resolve("work"));
            serial.start();
            try {
                ServiceProbe probe = new ServiceProbe(serial);
                Eventually.await("pty open", Duration.ofSeconds(10), () -> probe.status("ttyCP").available());
                byte[] huge = new byte[3_000_000];
                new Random(18).nextBytes(huge);
                cancelledAtFirstProgress(probe, "ttyCP", "ymodem:put HUGE.BIN", new Attachment("HUGE.BIN", huge));
                // rb was told (CAN CAN) and gave up: whatever it kept is not the whole file
                Path partial = dir.resolve("HUGE.BIN");
                assertTrue(!Files.exists(partial) || Files.size(partial) < huge.length,
                        "rb stopped before the end; socat: " + socat.log());
                ServiceProbe.Answer got = probe.send("ttyCP", "ymodem:get MISSION.LOG", T);
                assertTrue(got.ok(), "the get after a cancelled put: " + got.text());
                assertArrayEquals(log, assertInstanceOf(FileData.class, got.last().footer().result()).data());
                ServiceProbe.Answer listing = probe.send("ttyCP", "dir", T);
                assertTrue(listing.ok() && listing.text().contains("MISSION.LOG") && !listing.text().contains("Bad command"),
                        listing.text());
            } finally {
                serial.stop();
            }
        }
    }

    @Test
    @SuppressWarnings("try")
    void aRefusedTransferStartIsTriedOnceMoreOnACleanLine() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("vehicle"));
        byte[] log = new byte[5_000];
        new Random(13).nextBytes(log);
        Files.write(dir.resolve("A.LOG"), log);
        Path pty = tmp.resolve("ttyRF");
        try (Socat socat = vehicle(dir, pty, "REFUSE_ONCE=1 ")) {
            SerialPortServer serial = new SerialPortServer("testhost", List.of(link(pty)), null, false, tmp.resolve("work"));
            serial.start();
            try {
                ServiceProbe probe = new ServiceProbe(serial);
                Eventually.await("pty open", Duration.ofSeconds(10), () -> probe.status("ttyRF").available());
                byte[] up = new byte[3_000];
                new Random(14).nextBytes(up);
                ServiceProbe.Answer put = probe.send("ttyRF", "ymodem:put B.BIN", new Attachment("B.BIN", up), T);
                assertTrue(put.ok(), put.text());
                assertArrayEquals(up, Files.readAllBytes(dir.resolve("B.BIN")));
                ServiceProbe.Answer got = probe.send("ttyRF", "ymodem:get A.LOG", T);
                assertTrue(got.ok(), got.text());
                assertArrayEquals(log, assertInstanceOf(FileData.class, got.last().footer().result()).data());
                List<String> notes = probe.console("ttyRF", ConsoleEntry.Kind.TRANSFER).stream().map(ConsoleEntry::text)
                        .filter(t -> t.contains("was refused")).toList();
                assertEquals(List.of("'yr' was refused; trying once more on a clean line",
                        "'ys A.LOG' was refused; trying once more on a clean line"), notes);
            } finally {
                serial.stop();
            }
        }
    }
}
