package org.ripv.services.serial.zmodem;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.services.serial.ymodem.ByteLink;

/** Which data bytes go out as ZDLE and a second byte: the protocol's seven, as lrzsz's sz sends them. */
class ZFrameWriterEscapesTest {

    @Test
    void onlyZdleDleXonXoffAndTheHighBitTwinsOfTheLastThreeAreEscaped() throws Exception {
        assertThat(escaped(false)).containsExactly(0x10, 0x11, 0x13, 0x18, 0x90, 0x91, 0x93);
    }

    @Test
    void aReceiverThatAsksForControlsEscapedGetsEveryControlCharacterEscaped() throws Exception {
        List<Integer> controls = new ArrayList<>();
        for (int c = 0; c < 256; c++) {
            if ((c & 0x60) == 0) {
                controls.add(c);
            }
        }
        assertThat(escaped(true)).containsExactlyElementsOf(controls);
    }

    /** The byte values a lone data byte is escaped for, each sent in a subpacket of its own. */
    private static List<Integer> escaped(boolean controls) throws Exception {
        List<Integer> escaped = new ArrayList<>();
        for (int c = 0; c < 256; c++) {
            ByteArrayOutputStream wire = new ByteArrayOutputStream();
            ZFrameWriter w = new ZFrameWriter(new ByteLink() {
                @Override
                public int read(byte[] b, int o, int l, long t) {
                    return 0;
                }

                @Override
                public void write(byte[] b, int o, int l) {
                    wire.write(b, o, l);
                }
            });
            w.escapeControls(controls);
            w.data(new byte[] {(byte) c}, 0, 1, Zmodem.ZCRCE, true);
            byte[] out = wire.toByteArray();
            if ((out[0] & 0xFF) == Zmodem.ZDLE) {
                assertThat(out[1] & 0xFF).as("escaped %02x", c).isEqualTo(c ^ 0x40);
                escaped.add(c);
            } else {
                assertThat(out[0] & 0xFF).isEqualTo(c);
            }
        }
        return escaped;
    }
}
