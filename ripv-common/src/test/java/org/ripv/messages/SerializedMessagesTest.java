package org.ripv.messages;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.InvalidObjectException;
import java.io.ObjectInputFilter;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.wire.WireFilter;

/** The stream-free form must be byte for byte what ObjectOutputStream writes, and read back only what the filter allows. */
class SerializedMessagesTest {
    static byte[] streamed(Object o) throws Exception {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(b)) {
            out.writeObject(o);
        }
        return b.toByteArray();
    }

    static List<Message> plainMessages() {
        Header h = new Header(123456789012L, new IdBadge("100001", "alice"), List.of("operators", "db-reader"), "<S>::<h>",
                "<S>::<h>TTY1", "dir ünïcode ✓ " + "x".repeat(3000), Priority.URGENT, null);
        Header empty = new Header(0, new IdBadge("100002", "b"), List.of(), "", "", "", Priority.NORMAL, null);
        Footer f = new Footer("888888", Status.ERROR, ErrorCode.TIMEOUT, List.of("<S>::<h>", "RIPVServer"), "no answer", null);
        return List.of(new IncomingServerMessage(h), new IncomingServiceMessage(h), new OutgoingServiceMessage(h, f),
                new OutgoingServerMessage(h, f), new IncomingServerMessage(empty), new OutgoingServerMessage(empty, Footer.unanswered()));
    }

    @Test
    void writesExactlyWhatObjectOutputStreamWrites() throws Exception {
        for (Message m : plainMessages()) {
            byte[] fast = SerializedMessages.serialize(m);
            assertThat(fast).as("%s", m).isNotNull().isEqualTo(streamed(m));
            Message back = SerializedMessages.deserialize(fast, WireFilter.forFrames(1 << 20));
            assertThat(back).isNotNull().hasSameClassAs(m);
            assertThat(back.header()).isEqualTo(m.header());
            assertThat(back.footer()).isEqualTo(m.footer());
            try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(fast))) {
                assertThat(((Message) in.readObject()).header()).isEqualTo(m.header());
            }
        }
    }

    @Test
    void leavesAttachmentsAndResultsToTheStreams() throws Exception {
        assertThat(SerializedMessages.serialize(PackedMessageTest.sample())).isNull();
        assertThat(SerializedMessages.deserialize(streamed(PackedMessageTest.sample()), null)).isNull();
    }

    @Test
    void refusesWhatTheFilterRefusesAndOtherShapes() throws Exception {
        byte[] fast = SerializedMessages.serialize(plainMessages().get(0));
        ObjectInputFilter noPacked = info -> info.serialClass() == PackedMessage.class ? ObjectInputFilter.Status.REJECTED
                : ObjectInputFilter.Status.ALLOWED;
        assertThat(SerializedMessages.deserialize(fast, noPacked)).isNull();
        assertThat(SerializedMessages.deserialize(Arrays.copyOf(fast, fast.length + 1), null)).isNull();
        assertThat(SerializedMessages.deserialize(Arrays.copyOf(fast, fast.length - 1), null)).isNull();
        assertThat(SerializedMessages.deserialize(streamed("a string"), null)).isNull();
        ObjectInputFilter small = info -> info.streamBytes() > 100 ? ObjectInputFilter.Status.REJECTED
                : ObjectInputFilter.Status.ALLOWED;
        assertThat(SerializedMessages.deserialize(fast, small)).isNull();
    }

    @Test
    void malformedFieldsInTheRightShapeAreRefused() throws Exception {
        byte[] fast = SerializedMessages.serialize(plainMessages().get(0));
        byte[] kind = fast.clone();
        int kindAt = indexOfKind(fast);
        kind[kindAt] = 9;
        assertThatThrownBy(() -> SerializedMessages.deserialize(kind, null)).isInstanceOf(InvalidObjectException.class)
                .hasMessageContaining("unknown message kind");
    }

    private static int indexOfKind(byte[] fast) throws Exception {
        byte[] other = SerializedMessages.serialize(new IncomingServiceMessage(plainMessages().get(0).header()));
        for (int i = 0; i < fast.length; i++) {
            if (fast[i] != other[i]) {
                return i;
            }
        }
        throw new AssertionError("same bytes");
    }
}
