package org.ripv.messages;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.ObjectOutputStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.wire.FrameCodec;
import org.ripv.wire.ProtocolException;

class PackedMessageTest {
    final FrameCodec codec = new FrameCodec(1 << 20);

    static OutgoingServerMessage sample() {
        Header h = new Header(9, new IdBadge("100001", "alice"), List.of("operators", "db-reader"), "<S>::<h>", "<S>::<h>TTY1",
                "dir ünïcode", Priority.URGENT, new Attachment("a.bin", new byte[] {0, 1, 2}));
        return new OutgoingServerMessage(h, new Footer("888888", Status.ERROR, ErrorCode.TIMEOUT, List.of("<S>::<h>", "RIPVServer"),
                "no answer", new Progress("x", 1, 2, 3.5)));
    }

    @Test
    void everyFieldSurvivesTheRoundTrip() throws Exception {
        OutgoingServerMessage m = sample();
        Message back = codec.decode(codec.encode(m));
        assertThat(back).isInstanceOf(OutgoingServerMessage.class);
        assertThat(back.header().withAttachment(null)).isEqualTo(m.header().withAttachment(null));
        assertThat(back.header().attachment().data()).containsExactly(0, 1, 2);
        assertThat(back.footer()).isEqualTo(m.footer());
        Message in = codec.decode(codec.encode(new IncomingServiceMessage(m.header())));
        assertThat(in).isInstanceOf(IncomingServiceMessage.class);
        assertThat(in.footer()).isEqualTo(Footer.unanswered());
    }

    /** Serializes a PackedMessage whose fields have been tampered with. */
    private byte[] tampered(int kind, byte[] fields) throws Exception {
        PackedMessage good = PackedMessage.pack(sample());
        Constructor<PackedMessage> c = PackedMessage.class.getDeclaredConstructor(byte.class, byte[].class, Attachment.class, Result.class);
        c.setAccessible(true);
        PackedMessage bad = c.newInstance((byte) kind, fields, null, null);
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (ObjectOutputStream o = new ObjectOutputStream(b)) {
            o.writeObject(bad);
        }
        assertThat(good).isNotNull();
        return b.toByteArray();
    }

    private static byte[] fieldsOf(Message m) throws Exception {
        Field f = PackedMessage.class.getDeclaredField("fields");
        f.setAccessible(true);
        return (byte[]) f.get(PackedMessage.pack(m));
    }

    @Test
    void tamperedPacksAreRejectedAsProtocolErrors() throws Exception {
        byte[] fields = fieldsOf(sample());
        assertThatThrownBy(() -> codec.decode(tampered(7, fields))).isInstanceOf(ProtocolException.class)
                .hasMessageContaining("unknown message kind");
        assertThatThrownBy(() -> codec.decode(tampered(3, Arrays.copyOf(fields, fields.length - 3))))
                .isInstanceOf(ProtocolException.class);
        assertThatThrownBy(() -> codec.decode(tampered(3, Arrays.copyOf(fields, fields.length + 1))))
                .isInstanceOf(ProtocolException.class).hasMessageContaining("trailing");
        byte[] hugeLength = fields.clone();
        hugeLength[8] = 0x7f; // the first text's length
        assertThatThrownBy(() -> codec.decode(tampered(3, hugeLength))).isInstanceOf(ProtocolException.class);
        assertThatThrownBy(() -> codec.decode(tampered(3, null))).isInstanceOf(ProtocolException.class);
        byte[] badId = fields.clone();
        badId[12] = 'x'; // the client id is no longer six digits
        assertThatThrownBy(() -> codec.decode(tampered(3, badId))).isInstanceOf(ProtocolException.class);
    }
}
