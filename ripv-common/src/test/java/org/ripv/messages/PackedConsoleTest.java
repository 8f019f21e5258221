package org.ripv.messages;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.ripv.messages.PackedTableTest.roundTrip;

import java.io.InvalidObjectException;
import java.lang.reflect.Field;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.wire.FrameCodec;

/** A ConsoleBatch crosses object streams as one packed array, comes back equal and small; bad data is refused. */
class PackedConsoleTest {
    private static final String BOX = "ripv-server/SerialPortServer/ttyS0";

    @Test
    void everyKindOfEntrySurvivesTheTrip() throws Exception {
        List<ConsoleEntry> entries = List.of(
                new ConsoleEntry(1_700_000_000_123L, BOX, ConsoleEntry.Kind.LINE, "", "Glider ru29 at surface — Grüße 海", null, null, null),
                new ConsoleEntry(2L, BOX, ConsoleEntry.Kind.COMMAND, "alice", "callback 30", null, null, null),
                new ConsoleEntry(3L, BOX, ConsoleEntry.Kind.EVENT, "", "GPS fix", VehicleEvent.SURFACED, 41.6332, -70.5365),
                new ConsoleEntry(4L, "other/SerialPortServer/ttyS1", ConsoleEntry.Kind.TRANSFER, "bob", "ymodem:get 40 %", null, null, null),
                new ConsoleEntry(5L, BOX, ConsoleEntry.Kind.EVENT, "", "", VehicleEvent.WORKFLOW_FAILED, null, null),
                new ConsoleEntry(5L, BOX, ConsoleEntry.Kind.EVENT, "", "", VehicleEvent.DIVED, null, null, 1_700_000_000_123_001L));
        ConsoleBatch b = new ConsoleBatch(BOX, entries, 17, true);
        ConsoleBatch back = (ConsoleBatch) roundTrip(b);
        assertThat(back).isEqualTo(b);

        ConsoleBatch empty = new ConsoleBatch(BOX, List.of(), 0, false);
        assertThat(roundTrip(empty)).isEqualTo(empty);
    }

    @Test
    void aOneLinePushIsAboutHalfItsDefaultForm() throws Exception {
        ConsoleEntry line = ConsoleEntry.line(BOX, "bench 12 123456789012345 a line the vehicle printed");
        OutgoingServerMessage push = new OutgoingServerMessage(
                new Header(0, IdBadge.SERVER, List.of(), "", BOX, "?watch " + BOX, Priority.NORMAL, null),
                Footer.progress(Ids.FID_CONSOLE, "", new ConsoleBatch(BOX, List.of(line), 0, false)));
        FrameCodec codec = new FrameCodec(1 << 20);
        byte[] frame = codec.encode(push);
        // 526 bytes; the default form of the same push was 907, mostly class descriptors
        assertThat(frame.length).isLessThan(600);
        assertThat(((ConsoleBatch) codec.decode(frame).footer().result()).entries()).containsExactly(line);
    }

    @Test
    void corruptPackedDataIsRefused() throws Exception {
        PackedConsole p = new PackedConsole(new ConsoleBatch(BOX, List.of(ConsoleEntry.line(BOX, "x")), 0, false));
        Field data = PackedConsole.class.getDeclaredField("data");
        data.setAccessible(true);
        byte[] good = (byte[]) data.get(p);
        int countAt = 4 + 4 + BOX.length() + 8 + 1; // then per entry: time, seq, mailbox, kind, ...

        byte[] huge = good.clone();
        huge[countAt] = 0x7f; // an entry count far beyond the bytes sent must not make the reader allocate for it
        data.set(p, huge);
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class).hasMessageContaining("count");

        byte[] kind = good.clone();
        kind[countAt + 4 + 8 + 8 + 4] = 9; // no such kind
        data.set(p, kind);
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class).hasMessageContaining("enum index");

        byte[] event = good.clone();
        event[good.length - 2] = 0; // an event on a LINE is allowed, but...
        event[countAt + 4 + 8 + 8 + 4] = (byte) ConsoleEntry.Kind.EVENT.ordinal();
        event[good.length - 2] = (byte) 255; // ...an EVENT entry without its event is not
        data.set(p, event);
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class).hasMessageContaining("event");

        data.set(p, Arrays.copyOf(good, good.length - 1));
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class).hasMessageContaining("cut short");
        byte[] trailing = Arrays.copyOf(good, good.length + 1);
        data.set(p, trailing);
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class).hasMessageContaining("after its last entry");
        data.set(p, new byte[] {0, 0, 0, 9});
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class).hasMessageContaining("version");
        data.set(p, null);
        assertThatThrownBy(() -> roundTrip(p)).isInstanceOf(InvalidObjectException.class).hasMessageContaining("without data");
    }
}
