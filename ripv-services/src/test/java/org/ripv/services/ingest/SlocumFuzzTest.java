package org.ripv.services.ingest;

import java.io.ByteArrayInputStream;
import java.time.Duration;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.Size;
import org.junit.jupiter.api.Assertions;

/**
 * Fuzzing the binary decoder: whatever bytes arrive under a Slocum name, plain or compressed,
 * decoding gives rows or a {@link SlocumFormatException} — never another exception, a hang, or
 * memory beyond one cycle and one block. Bounded: a few seconds in {@code mvn verify}.
 */
class SlocumFuzzTest {
    private static final byte[] VALID;

    static {
        try {
            VALID = SlocumBadInputTest.sample();
        } catch (Exception e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    private static void decodesCleanly(byte[] data, String name) {
        Assertions.assertTimeoutPreemptively(Duration.ofSeconds(5), () -> {
            try {
                SlocumBinaryReaderTest.decode(new ByteArrayInputStream(data), name, null);
            } catch (SlocumFormatException expected) {
                // refused with an offset: what bad input must give
            }
        });
    }

    @Property(tries = 300)
    void randomBytesNamedSbd(@ForAll @Size(max = 4096) byte[] data) {
        decodesCleanly(data, "random.sbd");
    }

    @Property(tries = 300)
    void randomBytesNamedScd(@ForAll @Size(max = 4096) byte[] data) {
        decodesCleanly(data, "random.scd");
    }

    @Provide
    Arbitrary<byte[]> mutated() {
        return Arbitraries.integers().between(0, VALID.length - 1).list().ofMinSize(1).ofMaxSize(8).flatMap(at ->
                Arbitraries.bytes().list().ofSize(at.size()).map(values -> {
                    byte[] b = VALID.clone();
                    for (int i = 0; i < at.size(); i++) {
                        b[at.get(i)] = values.get(i);
                    }
                    return b;
                }));
    }

    @Property(tries = 500)
    void aValidFileWithBytesChanged(@ForAll("mutated") byte[] data) {
        decodesCleanly(data, "changed.sbd");
    }

    @Property(tries = 300)
    void aValidCompressedFileWithBytesChanged(@ForAll("mutated") byte[] data) {
        byte[] packed = Lz4Blocks.compress(VALID, 256);
        for (int i = 0; i < Math.min(8, packed.length); i++) {
            packed[(data[i % data.length] & 0xff) * 7 % packed.length] ^= data[(i + 1) % data.length];
        }
        decodesCleanly(packed, "changed.scd");
    }

    @Property(tries = 200)
    void aValidFileCutAnywhere(@ForAll("cut") int length) {
        decodesCleanly(java.util.Arrays.copyOf(VALID, length), "cut.sbd");
    }

    @Provide
    Arbitrary<Integer> cut() {
        return Arbitraries.integers().between(0, VALID.length);
    }
}
