package org.ripv.wire;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.ObjectOutputStream;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.TableResult;

class FrameCodecTest {
    final FrameCodec codec = new FrameCodec(64 * 1024);

    @Test
    void tenThousandMessagesOnOneStreamAllDecode() throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        for (int i = 0; i < 10_000; i++) {
            codec.write(out, new IncomingServerMessage(Header.request(i, "<X>::<h>TTY1", "echo " + i, Priority.URGENT)));
        }
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(bytes.toByteArray()));
        for (int i = 0; i < 10_000; i++) {
            Message m = codec.read(in);
            assertThat(m.header().messageId()).isEqualTo(i);
            assertThat(m.header().body()).isEqualTo("echo " + i);
        }
    }

    @Test
    void typedResultsSurviveTheFilter() throws Exception {
        TableResult t = new TableResult("SELECT 1", List.of("A", "B"), List.of("INTEGER", "VARCHAR"),
                List.of(new String[] {"1", null}, new String[] {"2", "two"}), true);
        OutgoingServerMessage m = new OutgoingServerMessage(Header.request(7, "", "SELECT 1", Priority.NORMAL),
                Footer.ok("666666", "2 rows", t).via("db").via("RIPVServer"));
        Message back = codec.decode(codec.encode(m));
        TableResult r = (TableResult) back.footer().result();
        assertThat(r.columns()).containsExactly("A", "B");
        assertThat(r.rows().get(0)).containsExactly("1", null);
        assertThat(r.truncated()).isTrue();
        assertThat(back.footer().route()).containsExactly("db", "RIPVServer");
    }

    @Test
    void rejectsWhatIsNotAMessage() throws Exception {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (ObjectOutputStream o = new ObjectOutputStream(b)) {
            o.writeObject(new ArrayList<>(List.of("a")));
        }
        assertThatThrownBy(() -> codec.decode(b.toByteArray())).isInstanceOf(ProtocolException.class)
                .hasMessageContaining("not a message");
    }

    @Test
    void turnsEveryHostileStreamIntoAProtocolException() {
        byte[][] hostile = {
            {(byte) 0xAC, (byte) 0xED, 0x00, 0x05, 0x7E, 0x70},
            {(byte) 0xAC, (byte) 0xED, 0x00, 0x05},
            {1, 2, 3},
            {(byte) 0xAC, (byte) 0xED, 0x00, 0x05, 0x73, 0x72, 0x00, 0x00},
        };
        for (byte[] h : hostile) {
            assertThatThrownBy(() -> codec.decode(h)).isInstanceOf(ProtocolException.class);
        }
    }

    @Test
    void refusesFramesOverTheLimitBothWays() {
        IncomingServerMessage big = new IncomingServerMessage(Header.request(1, "", "x".repeat(70_000), Priority.NORMAL));
        assertThatThrownBy(() -> codec.encode(big)).isInstanceOf(ProtocolException.class).hasMessageContaining("frame limit");
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(new byte[] {0x7f, 0, 0, 0}));
        assertThatThrownBy(() -> codec.read(in)).isInstanceOf(ProtocolException.class).hasMessageContaining("frame length");
    }

    @Test
    void checksTheGreeting() throws Exception {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        FrameCodec.writeGreeting(new DataOutputStream(b));
        FrameCodec.readGreeting(new DataInputStream(new ByteArrayInputStream(b.toByteArray())));
        assertThatThrownBy(() -> FrameCodec.readGreeting(new DataInputStream(new ByteArrayInputStream("GET / HTTP/1.1".getBytes()))))
                .isInstanceOf(ProtocolException.class).hasMessageContaining("not a RIPV peer");
    }
}
