package org.ripv.wire;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Message;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.PackedRows;
import org.ripv.messages.Priority;
import org.ripv.messages.TableResult;

/** A page of packed rows written straight from its gathered bytes is the frame {@code encode} makes, and reads back. */
class FramedPageTest {
    private static OutgoingServerMessage page(int rows) {
        PackedRows.Builder b = PackedRows.builder(3);
        for (int i = 0; i < rows; i++) {
            b.cell(Integer.toString(i));
            b.cell(i % 7 == 0 ? null : "Grüße 海 " + i);
            b.cell("2002-04-02 13:00:00.0");
            b.endRow();
        }
        TableResult t = new TableResult("SELECT * FROM t", List.of("N", "S", "T"), List.of("INTEGER", "VARCHAR", "TIMESTAMP"),
                b.build(), false);
        return new OutgoingServerMessage(Header.request(9, "<DatabaseServer>::<h>TTY1", "SELECT * FROM t", Priority.NORMAL),
                Footer.progress("666666", "rows 1-" + rows, t).via("RIPVServer"));
    }

    @Test
    void aPageGoesOutAsOneFrameOfTheSameBytesAndComesBackWhole() throws Exception {
        FrameCodec codec = new FrameCodec(FrameCodec.DEFAULT_MAX_FRAME);
        OutgoingServerMessage m = page(20_000);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        codec.write(out, m);
        codec.write(out, page(3));
        byte[] body = codec.encode(m);
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(bytes.toByteArray()));
        assertThat(in.readInt()).isEqualTo(body.length);
        in.reset();
        Message back = codec.read(in);
        TableResult t = (TableResult) back.footer().result();
        assertThat(t.rows()).hasSize(20_000);
        assertThat(t.rows().get(19_998)).containsExactly("19998", "Grüße 海 19998", "2002-04-02 13:00:00.0");
        assertThat(t.rows().get(7)).containsExactly("7", null, "2002-04-02 13:00:00.0");
        assertThat(((TableResult) codec.read(in).footer().result()).rows()).hasSize(3);
        assertThat(in.available()).isZero();
    }

    @Test
    void aPageOverTheFrameLimitIsRefusedBeforeAByteIsWritten() throws Exception {
        FrameCodec small = new FrameCodec(64 * 1024);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        assertThatThrownBy(() -> small.write(new DataOutputStream(bytes), page(20_000))).isInstanceOf(ProtocolException.class)
                .hasMessageContaining("over the frame limit");
        assertThat(bytes.size()).isZero();
    }
}
