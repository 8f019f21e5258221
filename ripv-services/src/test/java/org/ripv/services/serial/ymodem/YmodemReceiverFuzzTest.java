package org.ripv.services.serial.ymodem;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Assertions;

/**
 * Fuzzing the YMODEM receiver (issue 10): whatever a vehicle sends — noise, packets with good
 * CRCs but nonsense in them, lying block-0 lengths, hostile names, stray EOT and CAN — receiving
 * ends with files or a {@link YmodemException} (or the link's end), never another exception, a
 * hang, or more bytes stored than were sent. Bounded: a few seconds in {@code mvn verify}.
 */
class YmodemReceiverFuzzTest {
    static final YmodemConfig FAST = YmodemConfig.lrzsz().withTimeouts(Duration.ofMillis(300), Duration.ofMillis(20),
            Duration.ofMillis(50), Duration.ofMillis(20));

    /** The harness's own end of input: the vehicle's bytes ran out and the link closed. */
    static final class Exhausted extends EOFException {
        private static final long serialVersionUID = 1L;
    }

    /** Plays the given bytes, then reports the link closed; what the receiver writes is dropped. */
    static final class ScriptedLink implements ByteLink {
        private final byte[] script;
        private int at;

        ScriptedLink(byte[] script) {
            this.script = script;
        }

        @Override
        public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
            if (at >= script.length) {
                throw new Exhausted();
            }
            int n = Math.min(len, Math.min(script.length - at, 1 + (at % 97))); // uneven chunks
            System.arraycopy(script, at, buffer, offset, n);
            at += n;
            return n;
        }

        @Override
        public void write(byte[] buffer, int offset, int len) {
        }
    }

    /** Keeps files in memory and counts what was stored. */
    static final class CountingSink implements FileSink {
        long stored;

        @Override
        public OutputStream begin(FileHeader file) {
            FileNames.requirePlain(file.name());
            return new ByteArrayOutputStream() {
                @Override
                public void write(byte[] b, int off, int len) {
                    stored += len;
                }

                @Override
                public void write(int b) {
                    stored++;
                }
            };
        }

        @Override
        public void complete(FileHeader file) {
        }

        @Override
        public void discard(FileHeader file) {
        }
    }

    private static void receivesCleanly(byte[] script) {
        Assertions.assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            CountingSink sink = new CountingSink();
            try {
                List<FileHeader> files = new YmodemReceiver(new ScriptedLink(script), FAST, null).receiveBatch(sink);
                assertThat(files).allSatisfy(f -> FileNames.requirePlain(f.name()));
            } catch (YmodemException | Exhausted expected) {
                // a clean failure, or the link closed
            }
            assertThat(sink.stored).as("stored no more than was sent").isLessThanOrEqualTo(script.length);
        });
    }

    @Property(tries = 300)
    void arbitraryBytes(@ForAll byte[] noise) {
        receivesCleanly(noise);
    }

    @Property(tries = 300)
    void packetsWithGoodCrcsAndHostileContent(@ForAll("sessions") byte[] script) {
        receivesCleanly(script);
    }

    @Provide
    Arbitrary<byte[]> sessions() {
        Arbitrary<byte[]> piece = Arbitraries.frequencyOf(
                net.jqwik.api.Tuple.of(4, blockZero()),
                net.jqwik.api.Tuple.of(4, dataPacket()),
                net.jqwik.api.Tuple.of(1, Arbitraries.just(new byte[] {(byte) YmodemIo.EOT})),
                net.jqwik.api.Tuple.of(1, Arbitraries.just(new byte[] {(byte) YmodemIo.CAN, (byte) YmodemIo.CAN})),
                net.jqwik.api.Tuple.of(1, Arbitraries.bytes().array(byte[].class).ofMaxSize(40)));
        return piece.list().ofMaxSize(12).map(parts -> {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            parts.forEach(out::writeBytes);
            return out.toByteArray();
        });
    }

    /** Block 0: a name (hostile ones included), NUL, a length that may lie, and junk. */
    private Arbitrary<byte[]> blockZero() {
        Arbitrary<String> name = Arbitraries.oneOf(Arbitraries.strings().ofMaxLength(40),
                Arbitraries.of("MISSION1.LOG", "../../permit.txt", "/etc/passwd", ".hidden", "a\\b", "x".repeat(300), "",
                        "C:\\GLIDER.CFG", "nul\u0001x"));
        Arbitrary<String> length = Arbitraries.oneOf(Arbitraries.longs().map(v -> Long.toString(v)),
                Arbitraries.of("0", "1", "128", "1025", "99999999999999999999", "-5", "x", ""));
        return Combinators.combine(name, length, Arbitraries.strings().ofMaxLength(20), Arbitraries.of(128, 1024))
                .as((n, l, rest, size) -> {
                    byte[] payload = new byte[size];
                    byte[] text = (n + "\0" + l + " " + rest).getBytes(StandardCharsets.UTF_8);
                    System.arraycopy(text, 0, payload, 0, Math.min(text.length, size));
                    return packet(0, payload);
                });
    }

    private Arbitrary<byte[]> dataPacket() {
        return Combinators.combine(Arbitraries.integers().between(0, 5), Arbitraries.of(128, 1024), Arbitraries.bytes())
                .as((seq, size, fill) -> {
                    byte[] payload = new byte[size];
                    java.util.Arrays.fill(payload, fill);
                    return packet(seq, payload);
                });
    }

    private static byte[] packet(int seq, byte[] payload) {
        byte[] p = new byte[payload.length + 5];
        p[0] = (byte) (payload.length == 128 ? YmodemIo.SOH : YmodemIo.STX);
        p[1] = (byte) seq;
        p[2] = (byte) ~seq;
        System.arraycopy(payload, 0, p, 3, payload.length);
        int crc = CRC16CCITT.compute(payload);
        p[p.length - 2] = (byte) (crc >> 8);
        p[p.length - 1] = (byte) crc;
        return p;
    }
}
