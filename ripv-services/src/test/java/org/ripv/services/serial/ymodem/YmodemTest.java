package org.ripv.services.serial.ymodem;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BiFunction;
import java.util.function.Predicate;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** YMODEM sender and receiver over an in-memory link, with faults injected on the way. */
class YmodemTest {
    static final YmodemConfig FAST = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(3),
            Duration.ofMillis(300), Duration.ofMillis(500), Duration.ofMillis(300));

    @TempDir
    Path dir;

    private final ExecutorService pool = Executors.newCachedThreadPool();
    private final MemoryLink[] link = MemoryLink.pair();
    private final MemoryLink senderEnd = link[0];
    private final MemoryLink receiverEnd = link[1];

    @AfterEach
    void close() {
        senderEnd.close();
        pool.shutdownNow();
    }

    static byte[] random(int size, long seed) {
        byte[] b = new byte[size];
        new Random(seed).nextBytes(b);
        return b;
    }

    private Future<List<FileHeader>> receive(YmodemConfig config) {
        return pool.submit(() -> new YmodemReceiver(receiverEnd, config, null).receiveBatch(new DirectorySink(dir)));
    }

    private List<FileHeader> transfer(YmodemConfig receiverConfig, SendFile... files) throws Exception {
        Future<List<FileHeader>> received = receive(receiverConfig);
        new YmodemSender(senderEnd, FAST, null).sendBatch(List.of(files));
        return received.get(30, TimeUnit.SECONDS);
    }

    private void assertReceived(String name, byte[] expected) throws IOException {
        assertArrayEquals(expected, Files.readAllBytes(dir.resolve(name)), name);
    }

    private void assertNoFiles() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(), files.toList(), "a failed transfer must leave no file, partial or whole");
        }
    }

    /** Applies {@code change} to the first write that matches, once. */
    static BiFunction<Integer, byte[], byte[]> once(Predicate<byte[]> which, java.util.function.UnaryOperator<byte[]> change) {
        AtomicInteger done = new AtomicInteger();
        return (i, b) -> which.test(b) && done.getAndIncrement() == 0 ? change.apply(b) : b;
    }

    static Predicate<byte[]> block(int seq) {
        return b -> b.length > 3 && (b[0] == 1 || b[0] == 2) && (b[1] & 0xFF) == seq;
    }

    /** The receiver's n-th ACK (from 1). */
    static Predicate<byte[]> nthAck(int n) {
        AtomicInteger acks = new AtomicInteger();
        return b -> b.length == 1 && b[0] == 0x06 && acks.incrementAndGet() == n;
    }

    @ParameterizedTest
    @ValueSource(ints = {0, 1, 127, 128, 129, 896, 897, 1023, 1024, 1025, 2048, 3 * 1024 + 128, 100_000})
    void sizesRoundTripExactly(int size) throws Exception {
        byte[] data = random(size, size);
        List<FileHeader> got = transfer(FAST, SendFile.of("F.BIN", data));
        assertEquals(1, got.size());
        assertEquals(size, got.get(0).length());
        assertReceived("F.BIN", data);
    }

    @Test
    void controlBytesAndPaddingBytesAreData() throws Exception {
        byte[] data = new byte[2000];
        for (int i = 0; i < data.length; i++) {
            data[i] = (byte) new int[] {0x18, 0x1A, 0x00, 0xFF, 0x01, 0x02, 0x04, 0x06, 0x15, 'C'}[i % 10];
        }
        data[data.length - 1] = 0x1A; // a file that really ends in SUB keeps it
        transfer(FAST, SendFile.of("CTRL.BIN", data));
        assertReceived("CTRL.BIN", data);
    }

    @Test
    void batchOfSeveralFilesWithBothEotStyles() throws Exception {
        for (boolean nakFirst : new boolean[] {true, false}) {
            MemoryLink[] l = MemoryLink.pair();
            Path out = Files.createDirectory(dir.resolve("eot-" + nakFirst));
            Future<List<FileHeader>> received = pool.submit(() ->
                    new YmodemReceiver(l[1], FAST.withEotNakFirst(nakFirst), null).receiveBatch(new DirectorySink(out)));
            byte[] a = random(5000, 1);
            byte[] b = new byte[0];
            byte[] c = random(1024, 3);
            new YmodemSender(l[0], FAST, null).sendBatch(List.of(SendFile.of("A.LOG", a), SendFile.of("B.EMPTY", b),
                    SendFile.of("C.BIN", c)));
            List<FileHeader> got = received.get(30, TimeUnit.SECONDS);
            assertEquals(List.of("A.LOG", "B.EMPTY", "C.BIN"), got.stream().map(FileHeader::name).toList());
            assertArrayEquals(a, Files.readAllBytes(out.resolve("A.LOG")));
            assertArrayEquals(b, Files.readAllBytes(out.resolve("B.EMPTY")));
            assertArrayEquals(c, Files.readAllBytes(out.resolve("C.BIN")));
            l[0].close();
        }
    }

    @Test
    void tenMegabytes() throws Exception {
        byte[] data = random(10 * 1024 * 1024 + 77, 10);
        transfer(FAST, SendFile.of("BIG.BIN", data));
        assertReceived("BIG.BIN", data);
    }

    @Test
    void lostBlockIsResentAfterTimeout() throws Exception {
        byte[] data = random(8000, 4);
        senderEnd.faults = once(block(3), b -> null);
        transfer(FAST, SendFile.of("LOST.BIN", data));
        assertReceived("LOST.BIN", data);
    }

    @Test
    void corruptedBlocksAreNakedAndResent() throws Exception {
        byte[] data = random(8000, 5);
        AtomicInteger corrupted = new AtomicInteger();
        senderEnd.faults = (i, b) -> {
            if (block(2).or(block(5)).test(b) && corrupted.get() < 3) {
                corrupted.incrementAndGet();
                byte[] bad = b.clone();
                bad[100] ^= 0x40; // flips a data bit: the CRC no longer matches
                return bad;
            }
            return b;
        };
        transfer(FAST, SendFile.of("NOISY.BIN", data));
        assertReceived("NOISY.BIN", data);
        assertEquals(3, corrupted.get());
    }

    @Test
    void damagedBlockNumberAndTruncatedBlockAreRejected() throws Exception {
        byte[] data = random(5000, 6);
        BiFunction<Integer, byte[], byte[]> badComplement = once(block(2), b -> {
            byte[] bad = b.clone();
            bad[2] = 0;
            return bad;
        });
        BiFunction<Integer, byte[], byte[]> truncated = once(block(4), b -> java.util.Arrays.copyOf(b, 500));
        senderEnd.faults = (i, b) -> truncated.apply(i, badComplement.apply(i, b));
        transfer(FAST, SendFile.of("DAMAGED.BIN", data));
        assertReceived("DAMAGED.BIN", data);
    }

    @Test
    void duplicatedBlockIsAcknowledgedAndDropped() throws Exception {
        byte[] data = random(8000, 7);
        senderEnd.faults = once(block(3), b -> {
            byte[] twice = new byte[b.length * 2];
            System.arraycopy(b, 0, twice, 0, b.length);
            System.arraycopy(b, 0, twice, b.length, b.length);
            return twice;
        });
        transfer(FAST, SendFile.of("DUP.BIN", data));
        assertReceived("DUP.BIN", data);
    }

    @Test
    void lostAckMakesSenderRepeatAndReceiverDropTheRepeat() throws Exception {
        byte[] data = random(6000, 8);
        receiverEnd.faults = once(nthAck(4), b -> null);
        transfer(FAST, SendFile.of("ACK.BIN", data));
        assertReceived("ACK.BIN", data);
    }

    @Test
    void lostAckOfBlockZeroIsRecovered() throws Exception {
        byte[] data = random(3000, 9);
        receiverEnd.faults = once(nthAck(1), b -> null);
        transfer(FAST, SendFile.of("ZERO.BIN", data));
        assertReceived("ZERO.BIN", data);
    }

    @Test
    void crcRequestAfterFirstDataBlockMeansResend() throws Exception {
        byte[] data = random(6000, 11);
        // the ACK of block 2 (ACKs: block 0, block 1, block 2) arrives as 'C'
        receiverEnd.faults = once(nthAck(3), b -> new byte[] {'C'});
        transfer(FAST, SendFile.of("C.BIN", data));
        assertReceived("C.BIN", data);
    }

    @Test
    void lostFinalAckIsTolerated() throws Exception {
        byte[] data = random(1000, 12);
        // ACKs: block 0, 1 data block, EOT, end-of-batch block 0
        Future<List<FileHeader>> received = receive(FAST.withEotNakFirst(false));
        receiverEnd.faults = once(nthAck(4), b -> null);
        new YmodemSender(senderEnd, FAST, null).sendBatch(List.of(SendFile.of("END.BIN", data)));
        received.get(10, TimeUnit.SECONDS);
        assertReceived("END.BIN", data);
    }

    @Test
    void receiverCancelAbortsSender() throws Exception {
        Future<Void> sending = pool.submit(() -> {
            new YmodemSender(senderEnd, FAST, null).sendBatch(List.of(SendFile.of("X.BIN", random(50_000, 1))));
            return null;
        });
        ScriptedPeer peer = new ScriptedPeer(receiverEnd);
        peer.send('C');
        assertEquals(0x01, peer.expectPacketStart());
        peer.skip(132);
        peer.send(0x06);
        peer.send('C');
        peer.expectPacketStart();
        peer.send(0x18, 0x18);
        ExecutionException e = assertThrows(ExecutionException.class, () -> sending.get(10, TimeUnit.SECONDS));
        assertTrue(e.getCause() instanceof YmodemException ye && ye.cancelledByPeer(), e.getCause().toString());
    }

    @Test
    void senderCancelAbortsReceiverAndLeavesNoFile() throws Exception {
        Future<List<FileHeader>> received = receive(FAST);
        ScriptedPeer peer = new ScriptedPeer(senderEnd);
        assertEquals('C', peer.next());
        peer.send(ScriptedPeer.packet(0, 128, "HALF.BIN\u00005000".getBytes(StandardCharsets.US_ASCII)));
        assertEquals(0x06, peer.next());
        assertEquals('C', peer.next());
        peer.send(ScriptedPeer.packet(1, 1024, random(1024, 2)));
        assertEquals(0x06, peer.next());
        peer.send(0x18, 0x18);
        ExecutionException e = assertThrows(ExecutionException.class, () -> received.get(10, TimeUnit.SECONDS));
        assertTrue(e.getCause() instanceof YmodemException ye && ye.cancelledByPeer(), e.getCause().toString());
        assertNoFiles();
    }

    @Test
    void silentSenderTimesOutWithoutFiles() throws Exception {
        Future<List<FileHeader>> received = receive(FAST.withTimeouts(Duration.ofSeconds(1), Duration.ofMillis(200),
                Duration.ofMillis(300), Duration.ofMillis(200)));
        ExecutionException e = assertThrows(ExecutionException.class, () -> received.get(10, TimeUnit.SECONDS));
        assertTrue(e.getCause().getMessage().contains("no YMODEM sender"), e.getCause().getMessage());
        assertNoFiles();
    }

    @Test
    void silentReceiverTimesOut() {
        YmodemConfig quick = FAST.withTimeouts(Duration.ofSeconds(1), Duration.ofMillis(200), Duration.ofMillis(300),
                Duration.ofMillis(200));
        YmodemException e = assertThrows(YmodemException.class,
                () -> new YmodemSender(senderEnd, quick, null).sendBatch(List.of(SendFile.of("A", new byte[10]))));
        assertTrue(e.getMessage().contains("timed out"), e.getMessage());
    }

    @Test
    void senderThatFallsSilentMidFileLeavesNoFile() throws Exception {
        Future<List<FileHeader>> received = receive(FAST);
        ScriptedPeer peer = new ScriptedPeer(senderEnd);
        assertEquals('C', peer.next());
        peer.send(ScriptedPeer.packet(0, 128, "GONE.BIN\u00003000".getBytes(StandardCharsets.US_ASCII)));
        assertEquals(0x06, peer.next());
        assertEquals('C', peer.next());
        peer.send(ScriptedPeer.packet(1, 1024, random(1024, 2)));
        assertEquals(0x06, peer.next());
        // then nothing: the receiver NAKs, gives up and cancels
        ExecutionException e = assertThrows(ExecutionException.class, () -> received.get(20, TimeUnit.SECONDS));
        assertTrue(e.getCause().getMessage().contains("timed out"), e.getCause().getMessage());
        assertNoFiles();
    }

    @Test
    void lrzszStyleSenderWithMixedBlocksAndNakedEot() throws Exception {
        Future<List<FileHeader>> received = receive(FAST);
        byte[] data = random(1200, 13);
        ScriptedPeer peer = new ScriptedPeer(senderEnd);
        assertEquals('C', peer.next());
        // lrzsz's block 0: name, length, octal mtime and mode, more fields, and bytes in the last two places
        byte[] info = new byte[128];
        byte[] fields = "MIX.BIN\u00001200 14712345670 100644 0 1 1200".getBytes(StandardCharsets.US_ASCII);
        System.arraycopy(fields, 0, info, 0, fields.length);
        info[126] = 0x04;
        info[127] = (byte) 0xB0;
        peer.send(ScriptedPeer.packet(0, 128, info));
        assertEquals(0x06, peer.next());
        assertEquals('C', peer.next());
        peer.send(ScriptedPeer.packet(1, 128, java.util.Arrays.copyOfRange(data, 0, 128)));
        assertEquals(0x06, peer.next());
        peer.send(ScriptedPeer.packet(2, 1024, java.util.Arrays.copyOfRange(data, 128, 1152)));
        assertEquals(0x06, peer.next());
        peer.send(ScriptedPeer.packet(3, 128, java.util.Arrays.copyOfRange(data, 1152, 1200)));
        assertEquals(0x06, peer.next());
        peer.send(0x04);
        assertEquals(0x15, peer.next(), "first EOT is NAKed");
        peer.send(0x04);
        assertEquals(0x06, peer.next());
        assertEquals('C', peer.next());
        peer.send(ScriptedPeer.packet(0, 128, new byte[0]));
        assertEquals(0x06, peer.next());
        List<FileHeader> got = received.get(10, TimeUnit.SECONDS);
        assertEquals(new FileHeader("MIX.BIN", 1200, 014712345670L, 0100644), got.get(0));
        assertReceived("MIX.BIN", data);
    }

    @Test
    void shortFileAtEotIsDiscarded() throws Exception {
        Future<List<FileHeader>> received = receive(FAST.withEotNakFirst(false));
        ScriptedPeer peer = new ScriptedPeer(senderEnd);
        assertEquals('C', peer.next());
        peer.send(ScriptedPeer.packet(0, 128, "SHORT.BIN\u00005000".getBytes(StandardCharsets.US_ASCII)));
        assertEquals(0x06, peer.next());
        assertEquals('C', peer.next());
        peer.send(ScriptedPeer.packet(1, 1024, random(1024, 2)));
        assertEquals(0x06, peer.next());
        peer.send(0x04);
        ExecutionException e = assertThrows(ExecutionException.class, () -> received.get(10, TimeUnit.SECONDS));
        assertTrue(e.getCause().getMessage().contains("1024 of 5000"), e.getCause().getMessage());
        assertNoFiles();
    }

    @Test
    void hostileNameInBlockZeroIsRefused() throws Exception {
        Future<List<FileHeader>> received = receive(FAST);
        ScriptedPeer peer = new ScriptedPeer(senderEnd);
        assertEquals('C', peer.next());
        peer.send(ScriptedPeer.packet(0, 128, "../..\u000010".getBytes(StandardCharsets.US_ASCII)));
        ExecutionException e = assertThrows(ExecutionException.class, () -> received.get(10, TimeUnit.SECONDS));
        assertTrue(e.getCause().getMessage().contains("refused file name"), e.getCause().getMessage());
        assertNoFiles();
    }

    @Test
    void crcMatchesTheStandardCheckValue() {
        assertEquals(0x31C3, CRC16CCITT.compute("123456789".getBytes(StandardCharsets.US_ASCII)));
        assertEquals(0, CRC16CCITT.compute(new byte[0]));
        byte[] all = new byte[1024];
        List<Integer> parts = new ArrayList<>();
        int whole = CRC16CCITT.compute(all);
        parts.add(CRC16CCITT.update(CRC16CCITT.compute(all, 0, 100), all, 100, 924));
        assertEquals(whole, parts.get(0));
    }
}
