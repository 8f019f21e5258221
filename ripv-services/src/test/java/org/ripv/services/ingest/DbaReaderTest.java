package org.ripv.services.ingest;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The DBA reader against the real files (counts made by {@link DbaFiles#count}, not the reader) and generated ones. */
class DbaReaderTest {

    record Read(DbaHeader header, long rows, long values, long noFix, long impossible, double firstLat, double firstLon) {}

    static Read read(byte[] file) throws Exception {
        try (DbaReader r = new DbaReader(new ByteArrayInputStream(file))) {
            double[] row = new double[r.header().sensors().size()];
            long values = 0;
            double lat = Double.NaN;
            double lon = Double.NaN;
            int latCol = r.header().column("m_lat") >= 0 ? r.header().column("m_lat") : r.header().column("m_gps_lat");
            int lonCol = r.header().column("m_lon") >= 0 ? r.header().column("m_lon") : r.header().column("m_gps_lon");
            while (r.next(row)) {
                assertThat(r.time(row)).as("line %d has a time", r.line()).isFinite();
                for (double v : row) {
                    if (!Double.isNaN(v)) {
                        values++;
                    }
                }
                if (Double.isNaN(lat) && !Double.isNaN(row[latCol])) {
                    lat = row[latCol];
                    lon = row[lonCol];
                }
            }
            return new Read(r.header(), r.rows(), values, r.noFix(), r.impossible(), lat, lon);
        }
    }

    @Test
    void cp388MatchesAnIndependentCountAndConvertsDeadReckonedPositions() throws Exception {
        byte[] file = DbaFiles.read(DbaFiles.shared("cp_388_2016_012_0_0.mrg"));
        DbaFiles.Count c = DbaFiles.count(file);
        Read r = read(file);
        assertThat(c.rows()).isEqualTo(23);
        assertThat(c.sensors()).isEqualTo(52);
        assertThat(r.rows()).isEqualTo(c.rows());
        assertThat(r.header().sensors()).hasSize(c.sensors());
        assertThat(r.values()).isEqualTo(c.values());
        assertThat(r.noFix()).isEqualTo(c.noFix()).isPositive();
        assertThat(r.impossible()).isZero();
        assertThat(r.header().vehicle()).isEqualTo("cp_388");
        assertThat(r.header().filename()).isEqualTo("cp_388-2016-012-0-0");
        // 3950.8632 -> 39 deg 50.8632 min; -7046.3354 -> 70 deg 46.3354 min W
        assertThat(r.firstLat()).isCloseTo(39.84772, within(1e-5));
        assertThat(r.firstLon()).isCloseTo(-70.77226, within(1e-5));
        assertThat(r.header().sensors().get(r.header().column("c_wpt_lat")).kind()).isEqualTo(Sensor.Kind.LATITUDE);
    }

    @Test
    void unit363MatchesAnIndependentCount() throws Exception {
        byte[] file = DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg"));
        DbaFiles.Count c = DbaFiles.count(file);
        Read r = read(file);
        assertThat(r.rows()).isEqualTo(c.rows()).isEqualTo(657);
        assertThat(r.header().sensors()).hasSize(c.sensors()).hasSize(29);
        assertThat(r.values()).isEqualTo(c.values());
        assertThat(r.noFix()).isEqualTo(c.noFix());
        assertThat(r.firstLat()).isCloseTo(50 + 11.2933 / 60, within(1e-6));
        assertThat(r.firstLon()).isCloseTo(-(144 + 33.6369 / 60), within(1e-6));
    }

    @Test
    void theBrokenHeaderIsRefusedWithItsLine() {
        byte[] file = DbaFiles.read(DbaFiles.shared("short_header.mrg"));
        assertThatThrownBy(() -> read(file)).isInstanceOf(DbaFormatException.class)
                .hasMessage("line 11: the file ends in the header after 10 of 14 tag lines")
                .satisfies(e -> assertThat(((DbaFormatException) e).line()).isEqualTo(11));
    }

    @Test
    void ddmmConversion() {
        assertThat(Degrees.fromDdmm(3950.8632, 90)).isEqualTo(39.84772); // rounded to 9 decimals, not 39.847719999999995
        assertThat(Double.toString(Degrees.fromDdmm(-14433.63700, 180))).isEqualTo("-144.560616667");
        assertThat(Degrees.fromDdmm(-7046.3354, 180)).isCloseTo(-70.772256667, within(1e-8));
        assertThat(Degrees.fromDdmm(0.5, 90)).isCloseTo(0.5 / 60, within(1e-9));
        assertThat(Degrees.fromDdmm(4075.0, 90)).isNaN();          // 75 minutes
        assertThat(Degrees.fromDdmm(9530.0, 90)).isNaN();          // 95 degrees of latitude
        assertThat(Degrees.fromDdmm(-17959.99, 180)).isCloseTo(-(179 + 59.99 / 60), within(1e-9));
        assertThat(Degrees.fromDdmm(Degrees.NO_FIX, 180)).isNaN();
    }

    @Test
    void aGenerated5000SensorFileIsReadWhole() throws Exception {
        byte[] file = DbaFiles.generate("big", 5000, 40, 7);
        DbaFiles.Count c = DbaFiles.count(file);
        Read r = read(file);
        assertThat(r.header().sensors()).hasSize(5000);
        assertThat(r.rows()).isEqualTo(40);
        assertThat(r.values()).isEqualTo(c.values());
    }

    @Test
    void sensorsPerCycleMayDisagreeByOneButNotTwo() throws Exception {
        String good = new String(DbaFiles.generate("g", 30, 5, 1), StandardCharsets.US_ASCII);
        assertThat(read(good.replace("sensors_per_cycle: 30", "sensors_per_cycle: 31").getBytes()).rows()).isEqualTo(5);
        assertThat(read(good.replace("sensors_per_cycle: 30", "sensors_per_cycle: 29").getBytes()).rows()).isEqualTo(5);
        assertThatThrownBy(() -> read(good.replace("sensors_per_cycle: 30", "sensors_per_cycle: 32").getBytes()))
                .hasMessage("line 15: the label line names 30 sensors but sensors_per_cycle is 32");
    }

    @Test
    void badRowsAreRefusedWithLineAndReason() {
        String good = new String(DbaFiles.generate("g", 10, 6, 2), StandardCharsets.US_ASCII);
        String[] lines = good.split("\n", -1);
        // line 18 is the first row (14 tags + 3 label lines)
        String[] fewer = lines.clone();
        fewer[19] = fewer[19].replaceFirst("\\S+\\s*$", "");
        assertThatThrownBy(() -> read(String.join("\n", fewer).getBytes()))
                .hasMessage("line 20: the row has 9 values for 10 sensors (the file is cut short?)");
        String[] more = lines.clone();
        more[20] = more[20] + " 1.5";
        assertThatThrownBy(() -> read(String.join("\n", more).getBytes()))
                .hasMessage("line 21: the row has more values than the 10 sensors");
        String[] word = lines.clone();
        word[17] = word[17].replaceFirst("^\\S+", "12:00");
        assertThatThrownBy(() -> read(String.join("\n", word).getBytes()))
                .hasMessage("line 18: value 1 (m_present_time) is '12:00', not a number");
        for (String bad : new String[] {"0x10", "Infinity", "1e5000", "1.5f", "--1", "."}) {
            String[] w = lines.clone();
            w[18] = w[18].replaceFirst("^\\S+", bad);
            assertThatThrownBy(() -> read(String.join("\n", w).getBytes())).as(bad)
                    .isInstanceOf(DbaFormatException.class).hasMessageStartingWith("line 19: value 1 (m_present_time)");
        }
        String[] blank = lines.clone();
        blank[18] = "";
        assertThatThrownBy(() -> read(String.join("\n", blank).getBytes()))
                .hasMessage("line 19: an empty line among the rows");
    }

    @Test
    void truncatedFilesAreRefused() {
        byte[] file = DbaFiles.generate("g", 30, 50, 3);
        // cut anywhere in the rows, but not at a line end: the last row is short or has no line end
        Random rnd = new Random(11);
        int headerEnd = new String(file, StandardCharsets.US_ASCII).indexOf("\n", DbaFiles.header("g", 30).length() - 2) + 1;
        for (int i = 0; i < 50; i++) {
            int cut = headerEnd + 1 + rnd.nextInt(file.length - headerEnd - 2);
            if (file[cut - 1] == '\n') {
                continue;
            }
            byte[] part = Arrays.copyOf(file, cut);
            assertThatThrownBy(() -> read(part)).as("cut at %d", cut).isInstanceOf(DbaFormatException.class);
        }
        // cut in the header or labels
        for (int cut : new int[] {0, 10, 200, DbaFiles.header("g", 30).length() - 5}) {
            byte[] part = Arrays.copyOf(file, cut);
            assertThatThrownBy(() -> read(part)).as("cut at %d", cut).isInstanceOf(DbaFormatException.class);
        }
    }

    @Test
    void garbageIsNotADbaFile() throws IOException {
        byte[] garbage = new byte[10 << 20];
        new Random(5).nextBytes(garbage);
        assertThatThrownBy(() -> read(garbage)).isInstanceOf(DbaFormatException.class)
                .hasMessageStartingWith("line 1: not a DBA file");
        byte[] text = "hello\nworld\n".getBytes();
        assertThatThrownBy(() -> read(text)).hasMessageStartingWith("line 1: not a DBA file: the first line is 'hello'");
        assertThat(DbaReader.looksLikeDba(garbage)).isFalse();
        assertThat(DbaReader.looksLikeDba(DbaFiles.read(DbaFiles.shared("short_header.mrg")))).isTrue();
    }
}
