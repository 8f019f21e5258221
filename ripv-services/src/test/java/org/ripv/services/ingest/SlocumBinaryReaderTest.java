package org.ripv.services.ingest;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Every shared real file against what dbd2asc prints for it, plain and LZ4-compressed, and the cache's life. */
class SlocumBinaryReaderTest {
    @TempDir
    Path tmp;

    static String decode(InputStream in, String name, SensorListCache cache) throws Exception {
        StringBuilder out = new StringBuilder();
        try (SlocumBinaryReader r = SlocumBinaryReader.open(in, name, cache)) {
            DbaText text = DbaText.start(out, r.tags(), r.sensors());
            double[] row = new double[r.sensors().size()];
            while (r.next(row)) {
                text.row(row);
            }
        }
        return out.toString();
    }

    @Test
    void everySharedFileDecodesExactlyAsDbd2ascPrintsIt() throws Exception {
        int files = 0;
        for (Path f : SlocumData.files()) {
            try (InputStream in = Files.newInputStream(f)) {
                assertThat(decode(in, f.getFileName().toString(), SlocumData.cache())).as(f.toString()).isEqualTo(SlocumData.expected(f));
            }
            files++;
        }
        assertThat(files).isEqualTo(22);
    }

    @Test
    void theLz4CompressedFormsDecodeToTheSameRows() throws Exception {
        for (Path f : SlocumData.files()) {
            byte[] plain = Files.readAllBytes(f);
            String name = f.getFileName().toString().replace(".sbd", ".scd").replace(".tbd", ".tcd");
            for (int block : new int[] {1, 100, 4096, 60_000}) {
                byte[] packed = Lz4Blocks.compress(plain, block);
                assertThat(decode(new ByteArrayInputStream(packed), name, SlocumData.cache())).as(name + " in blocks of " + block)
                        .isEqualTo(SlocumData.expected(f));
            }
        }
    }

    @Test
    void aMissingCacheIsNamedAndTheFileDecodesOnceItArrives() throws Exception {
        Path f = SlocumData.files().get(2);
        SensorListCache empty = new SensorListCache(tmp.resolve("cache"));
        byte[] data = Files.readAllBytes(f);
        assertThatThrownBy(() -> decode(new ByteArrayInputStream(data), f.getFileName().toString(), empty))
                .isInstanceOfSatisfying(MissingSensorListException.class, e -> {
                    assertThat(e.crc()).isEqualTo("6b016a2e");
                    assertThat(e.getMessage()).contains("6b016a2e.cac").contains("ymodem:get");
                });
        Path cac = SlocumData.dir().resolve("cac/6b016a2e.cac");
        assertThat(empty.accept("6B016A2E.CAC", Files.readAllBytes(cac))).isEqualTo("6b016a2e");
        assertThat(decode(new ByteArrayInputStream(data), f.getFileName().toString(), empty)).isEqualTo(SlocumData.expected(f));
    }

    @Test
    void aCacheOfAnotherListUnderTheCrcIsRefused() throws Exception {
        Path f = SlocumData.files().get(2);
        SensorListCache wrong = new SensorListCache(tmp.resolve("wrong"));
        byte[] other = Files.readAllBytes(SlocumData.dir().resolve("cac/426bd56d.cac"));
        // Refused at the door: its list's CRC, as the glider computes it, is not the name's (issue 33 item 7).
        assertThatThrownBy(() -> wrong.accept("6b016a2e.cac", other))
                .hasMessageContaining("does not hold the sensor list with CRC 6b016a2e (its list's CRC is 426bd56d)");
        // One an older version kept is not used either.
        Files.createDirectories(tmp.resolve("wrong"));
        Files.write(tmp.resolve("wrong/6b016a2e.cac"), other);
        assertThatThrownBy(() -> decode(Files.newInputStream(f), f.getFileName().toString(), wrong))
                .isInstanceOf(java.io.IOException.class).hasMessageContaining("does not hold the sensor list with CRC 6b016a2e")
                .hasMessageContaining("delete it and fetch the vehicle's own cache file");
        // Every real cache file is named by its list's CRC (the shared data's own, read-only files: tests of older
        // versions left made-up lists there, 0600, filed under made-up CRCs — what this item now refuses).
        try (var cacs = Files.list(SlocumData.dir().resolve("cac"))) {
            for (Path c : cacs.filter(c -> !isOwnerWritable(c)).toList()) {
                assertThat(SensorListCache.crcOf(Files.readAllBytes(c))).as(c.toString())
                        .isEqualTo(c.getFileName().toString().substring(0, 8).toLowerCase(java.util.Locale.ROOT));
            }
        }
        assertThatThrownBy(() -> wrong.accept("6b016a2e.txt", new byte[1])).hasMessageContaining("not a cache file name");
        assertThatThrownBy(() -> wrong.accept("12345678.cac", "hello\n".getBytes())).hasMessageContaining("line 1 is not a sensor-list line");
    }

    private static boolean isOwnerWritable(Path p) {
        try {
            return Files.getPosixFilePermissions(p).contains(java.nio.file.attribute.PosixFilePermission.OWNER_WRITE);
        } catch (java.io.IOException e) {
            return true;
        }
    }

    @Test
    void cPrintfGFormatting() {
        assertThat(DbaText.g(0.00121011, 6)).isEqualTo("0.00121011");
        assertThat(DbaText.g(1561011830.32263, 15)).isEqualTo("1561011830.32263");
        assertThat(DbaText.g(326306f, 6)).isEqualTo("326306");
        assertThat(DbaText.g(1234567.0, 6)).isEqualTo("1.23457e+06");
        assertThat(DbaText.g(0.0000123, 6)).isEqualTo("1.23e-05");
        assertThat(DbaText.g(-2.5, 6)).isEqualTo("-2.5");
        assertThat(DbaText.g(-0.0, 6)).isEqualTo("-0");
        assertThat(DbaText.g(100000, 6)).isEqualTo("100000");
        assertThat(DbaText.g(1e100, 15)).isEqualTo("1e+100");
    }
}
