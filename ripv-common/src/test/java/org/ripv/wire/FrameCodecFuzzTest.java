package org.ripv.wire;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.time.Duration;
import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.Tuple;
import org.junit.jupiter.api.Assertions;
import org.ripv.messages.Attachment;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.VehicleEvent;

/**
 * Fuzzing the frame decoder (issue 10): whatever bytes a socket delivers, reading a frame gives a
 * message or a {@link ProtocolException} (or EOF when the bytes run out) — never another exception,
 * a hang, or an allocation beyond the frame limit. Bounded: a few seconds in {@code mvn verify}.
 */
class FrameCodecFuzzTest {
    private static final FrameCodec CODEC = new FrameCodec(64 * 1024);
    private static final byte[] VALID;
    /** A console push: its batch travels in its own packed form (PackedConsole). */
    private static final byte[] VALID_PUSH;

    static {
        try {
            VALID = CODEC.encode(new IncomingServerMessage(new Header(7, new IdBadge("123456", "alice"), List.of("operators"),
                    "", "<SerialPortServer>::<h>ttyV0", "dir", Priority.NORMAL, new Attachment("a.bin", new byte[] {1, 2, 3}))));
            String box = "<SerialPortServer>::<h>ttyV0";
            VALID_PUSH = CODEC.encode(new OutgoingServerMessage(new Header(0, IdBadge.SERVER, List.of(), "", box, "?watch " + box,
                    Priority.NORMAL, null), Footer.progress(Ids.FID_CONSOLE, "", new ConsoleBatch(box, List.of(
                    ConsoleEntry.line(box, "Glider ru29 at surface"),
                    ConsoleEntry.event(box, VehicleEvent.SURFACED, "GPS Location: 4137.994 N -7032.188 E", 41.63, -70.54)),
                    3, false))));
        } catch (Exception e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    /** Decodes, allowing only a message or ProtocolException; the time limit only catches a hang (a loaded machine is slow, not stuck). */
    private static void decodesCleanly(byte[] body) {
        Assertions.assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            try {
                Message m = CODEC.decode(body);
                assertThat(m).isNotNull();
            } catch (ProtocolException expected) {
                // a clean refusal
            }
        });
    }

    @Property(tries = 400)
    void arbitraryBytesDecodeToAMessageOrAProtocolException(@ForAll byte[] body) {
        decodesCleanly(body);
    }

    @Property(tries = 400)
    void mutatedValidFramesDecodeCleanly(@ForAll("mutations") byte[] body) {
        decodesCleanly(body);
    }

    @Property(tries = 400)
    void mutatedConsolePushesDecodeCleanly(@ForAll("pushMutations") byte[] body) {
        decodesCleanly(body);
    }

    @Property(tries = 200)
    void framesOnAStreamReadCleanly(@ForAll("lengthPrefixed") byte[] stream) {
        Assertions.assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            DataInputStream in = new DataInputStream(new ByteArrayInputStream(stream));
            try {
                while (true) {
                    assertThat(CODEC.read(in)).isNotNull();
                }
            } catch (ProtocolException | EOFException expected) {
                // refused, or the bytes ran out between or inside frames
            }
        });
    }

    /** A valid serialized message with bytes flipped, inserted, cut or overwritten. */
    @Provide
    Arbitrary<byte[]> mutations() {
        return mutationsOf(VALID);
    }

    @Provide
    Arbitrary<byte[]> pushMutations() {
        return mutationsOf(VALID_PUSH);
    }

    private static Arbitrary<byte[]> mutationsOf(byte[] valid) {
        Arbitrary<Integer> at = Arbitraries.integers().between(0, valid.length - 1);
        Arbitrary<Byte> value = Arbitraries.bytes();
        Arbitrary<Tuple.Tuple3<Integer, Integer, Byte>> edit = Arbitraries.integers().between(0, 3)
                .flatMap(kind -> at.flatMap(i -> value.map(v -> Tuple.of(kind, i, v))));
        return edit.list().ofMinSize(1).ofMaxSize(8).map(edits -> {
                    byte[] b = valid.clone();
                    for (var e : edits) {
                        int i = Math.min(e.get2(), b.length - 1);
                        switch (e.get1()) {
                            case 0 -> b[i] ^= (byte) (1 << (e.get3() & 7));
                            case 1 -> b[i] = e.get3();
                            case 2 -> b = java.util.Arrays.copyOf(b, Math.max(1, i));
                            default -> {
                                byte[] longer = new byte[b.length + 1];
                                System.arraycopy(b, 0, longer, 0, i);
                                longer[i] = e.get3();
                                System.arraycopy(b, i, longer, i + 1, b.length - i);
                                b = longer;
                            }
                        }
                    }
                    return b;
                });
    }

    /** Length prefixes (in and out of range, lying about what follows) and bodies. */
    @Provide
    Arbitrary<byte[]> lengthPrefixed() {
        Arbitrary<Integer> length = Arbitraries.oneOf(Arbitraries.integers(), Arbitraries.integers().between(-2, 2),
                Arbitraries.just(VALID.length), Arbitraries.integers().between(1, 70_000));
        Arbitrary<byte[]> body = Arbitraries.oneOf(Arbitraries.just(VALID), mutations(),
                Arbitraries.bytes().array(byte[].class).ofMaxSize(512));
        Arbitrary<Tuple.Tuple2<Integer, byte[]>> frame = length.flatMap(n -> body.map(b -> Tuple.of(n, b)));
        return frame.list().ofMaxSize(4).map(frames -> {
                    java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
                    for (var f : frames) {
                        int n = f.get1();
                        out.write(n >>> 24);
                        out.write(n >>> 16);
                        out.write(n >>> 8);
                        out.write(n);
                        out.writeBytes(f.get2());
                    }
                    return out.toByteArray();
                });
    }
}
