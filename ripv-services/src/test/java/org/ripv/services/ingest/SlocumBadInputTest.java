package org.ripv.services.ingest;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Every kind of bad input the issue names is refused with the file, the byte offset and the reason; the encoder round-trips. */
class SlocumBadInputTest {
    static final List<SlocumSensor> SENSORS = List.of(new SlocumSensor("m_present_time", "timestamp", 8),
            new SlocumSensor("m_depth", "m", 4), new SlocumSensor("m_state", "enum", 1), new SlocumSensor("m_count", "nodim", 2));

    static byte[] sample() throws Exception {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        Map<String, String> tags = new LinkedHashMap<>();
        tags.put("full_filename", "unit_1-2024-001-0-0");
        tags.put("filename_extension", "sbd");
        SlocumEncoder e = SlocumEncoder.start(b, tags, SENSORS);
        for (int i = 0; i < 50; i++) {
            e.cycle(new double[] {1.7e9 + i, i % 3 == 0 ? Double.NaN : 10.5f, i % 4, -300 + i});
        }
        e.end();
        return b.toByteArray();
    }

    static String decode(byte[] data, String name) throws Exception {
        return SlocumBinaryReaderTest.decode(new ByteArrayInputStream(data), name, null);
    }

    @Test
    void theEncodersFilesDecodeToItsValues() throws Exception {
        List<String> rows = decode(sample(), "a.sbd").lines().skip(17).toList();
        assertThat(rows).hasSize(50);
        assertThat(rows.get(0)).isEqualTo("1700000000 NaN 0 -300 ");
        assertThat(rows.get(1)).isEqualTo("1700000001 10.5 1 -299 ");
        assertThat(rows.get(2)).as("the same value again: state 1, printed").isEqualTo("1700000002 10.5 2 -298 ");
    }

    @Test
    void theSharedFilesReencodedDecodeToTheSameText() throws Exception {
        for (Path f : SlocumData.files()) {
            ByteArrayOutputStream b = new ByteArrayOutputStream();
            try (SlocumBinaryReader r = SlocumBinaryReader.open(Files.newInputStream(f), f.toString(), SlocumData.cache())) {
                Map<String, String> tags = new LinkedHashMap<>();
                for (String k : List.of("the8x3_filename", "full_filename", "filename_extension", "mission_name", "fileopen_time")) {
                    tags.put(k, r.tags().get(k));
                }
                SlocumEncoder e = SlocumEncoder.start(b, tags, r.sensors());
                double[] row = new double[r.sensors().size()];
                while (r.next(row)) {
                    e.cycle(row);
                }
                e.end();
            }
            assertThat(decode(b.toByteArray(), f.getFileName().toString())).as(f.toString()).isEqualTo(SlocumData.expected(f));
        }
    }

    /** Rows read from {@code data} and what the reader says it left out. */
    static Map.Entry<Integer, String> readAll(byte[] data) throws Exception {
        try (SlocumBinaryReader r = new SlocumBinaryReader(new ByteArrayInputStream(data), "cut.sbd", null)) {
            double[] row = new double[r.sensors().size()];
            int rows = 0;
            while (r.next(row)) {
                rows++;
            }
            return Map.entry(rows, r.leftOut());
        }
    }

    @Test
    void aFileCutInItsCyclesIsReadUpToItsLastWholeCycleAndSaysWhatItLeft() throws Exception {
        byte[] good = sample();
        assertThat(readAll(good)).isEqualTo(Map.entry(50, ""));
        // the end tag lost (a call cut at the very end): every cycle, and it says so
        var noEnd = readAll(java.util.Arrays.copyOf(good, good.length - 1));
        assertThat(noEnd.getKey()).isEqualTo(50);
        assertThat(noEnd.getValue()).startsWith("the file ends after 51 cycles without its end tag 'X': read up to its last"
                + " whole cycle (byte " + (good.length - 1) + "), as dbd2asc does");
        // cut inside the last cycle: that cycle is left out, with how many bytes of it there were
        var cut = readAll(java.util.Arrays.copyOf(good, good.length - 4));
        assertThat(cut.getKey()).isEqualTo(49);
        assertThat(cut.getValue()).startsWith("the file ends after 50 cycles without its end tag 'X' (")
                .contains(" bytes of a cut cycle left out)");
        // and the DBA text dbd2asc would print: the same rows as the whole file, less the cut one
        List<String> whole = decode(good, "a.sbd").lines().skip(17).toList();
        assertThat(decode(java.util.Arrays.copyOf(good, good.length - 4), "a.sbd").lines().skip(17).toList())
                .isEqualTo(whole.subList(0, 49));
    }

    @Test
    void badInputIsRefusedWithTheOffsetAndTheReason() throws Exception {
        byte[] good = sample();
        String text = new String(good, StandardCharsets.ISO_8859_1);
        int known = text.indexOf("sa\u0012\u0034");
        assertThatThrownBy(() -> SlocumBinaryFiles.dba("empty.sbd", new byte[0], null)).hasMessage("empty.sbd: byte 0: the file is empty (0 bytes)");
        for (int cut : new int[] {5, known - 3, known + 3}) {
            assertThatThrownBy(() -> decode(java.util.Arrays.copyOf(good, cut), "cut.sbd")).as("cut at " + cut)
                    .isInstanceOf(SlocumFormatException.class).hasMessageContaining("truncated").hasMessageStartingWith("cut.sbd: byte ");
        }
        byte[] wrongFloat = good.clone();
        wrongFloat[known + 5] ^= 1;
        assertThatThrownBy(() -> decode(wrongFloat, "f.sbd")).hasMessage("f.sbd: byte " + (known + 4)
                + ": the known float is " + Float.intBitsToFloat(java.nio.ByteBuffer.wrap(wrongFloat, known + 4, 4).getInt()) + ", not 123.456");
        byte[] wrongOrder = good.clone();
        wrongOrder[known + 2] = 0x56;
        assertThatThrownBy(() -> decode(wrongOrder, "o.sbd")).hasMessageContaining("byte " + (known + 2))
                .hasMessageContaining("not 0x1234 in either byte order");
        assertThatThrownBy(() -> decode(text.replace("encoding_ver:    5", "encoding_ver:    4").getBytes(StandardCharsets.ISO_8859_1), "v.sbd"))
                .hasMessageContaining("encoding version '4' is not one this decoder knows (5)");
        assertThatThrownBy(() -> decode(text.replace("total_num_sensors:    4", "total_num_sensors:    1000000000")
                .getBytes(StandardCharsets.ISO_8859_1), "big.sbd"))
                .hasMessageContaining("total_num_sensors is 1000000000, not between 1 and 65536");
        byte[] badTag = good.clone();
        badTag[known + 16] = 'q';
        assertThatThrownBy(() -> decode(badTag, "t.sbd")).hasMessage("t.sbd: byte " + (known + 16)
                + ": expected a data cycle ('d') or the end ('X'), found byte 0x71 (cycle 1)");
        byte[] noise = new byte[100_000];
        new java.util.Random(22).nextBytes(noise);
        assertThatThrownBy(() -> decode(noise, "noise.sbd")).hasMessageStartingWith("noise.sbd: byte 0: not a Slocum binary file");
    }

    @Test
    void aCorruptLz4BlockIsRefusedWithItsOffset() throws Exception {
        byte[] packed = Lz4Blocks.compress(sample(), 200);
        int second = 2 + ((packed[0] & 0xff) << 8 | packed[1] & 0xff);
        byte[] broken = packed.clone();
        for (int i = second + 2; i < Math.min(broken.length, second + 12); i++) {
            broken[i] = (byte) 0xff;
        }
        assertThatThrownBy(() -> decode(broken, "c.scd")).isInstanceOf(SlocumFormatException.class)
                .hasMessageContaining("c.scd: byte " + second).hasMessageContaining("LZ4 block");
        assertThatThrownBy(() -> decode(java.util.Arrays.copyOf(packed, second + 5), "c.scd"))
                .hasMessageContaining("ends inside an LZ4 block");
    }
}
