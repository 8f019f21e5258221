package org.ripv.dac;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.ingest.Lz4Blocks;
import org.ripv.services.ingest.SensorListCache;
import org.ripv.services.ingest.SlocumEncoder;
import org.ripv.services.ingest.SlocumSensor;

/**
 * Bad input gets a clear refusal and leaves nothing in the output folder: a call with no science
 * file, a dive that never turns, a CTD that gave only NaN, a clock that steps back, an LZ4 bomb,
 * metadata with missing and wrong-typed fields. The bad science files are rosie_713's real
 * .tbd re-encoded with one thing changed.
 */
class DacBadInputTest {
    static final String SEG = "rosie_713-2019-166-0-157";

    static DacRun pipeline(Path meta) throws DacException {
        return new DacRun(new SegmentReader(new SensorListCache(DacFixtures.cache())), ProfileSplitter.defaults(),
                new ProfileWriter(Metadata.read(meta), QcConfig.none()), new ProfileChecker());
    }

    /** The real .tbd with each row changed by {@code edit}, written beside a copy of the real .sbd. */
    static List<Path> edited(Path dir, SlocumEncoder.Edit edit) throws Exception {
        byte[] tbd = Files.readAllBytes(DacFixtures.raw(SEG + ".tbd"));
        Path t = dir.resolve(SEG + ".tbd");
        Files.write(t, SlocumEncoder.recode(tbd, new SensorListCache(DacFixtures.cache()), "tbd", List.of(), edit));
        Path s = dir.resolve(SEG + ".sbd");
        Files.copy(DacFixtures.raw(SEG + ".sbd"), s);
        return List.of(s, t);
    }

    static int column(String name) throws Exception {
        List<String> names = new java.util.ArrayList<>();
        DacFixtures.rows(DacFixtures.shared().resolve("expected/" + SEG + ".tbd.dbd2asc.txt"), names);
        return names.indexOf(name);
    }

    static void refused(List<Path> files, Path out, String message) {
        assertThatThrownBy(() -> pipeline(DacFixtures.meta()).run(files, out)).isInstanceOf(DacException.class).hasMessageContaining(message);
        assertThat(out.toFile().list()).as("nothing written").isEmpty();
    }

    @Test
    void aCallWithNoScienceFile(@TempDir Path in, @TempDir Path out) throws Exception {
        Path s = in.resolve(SEG + ".sbd");
        Files.copy(DacFixtures.raw(SEG + ".sbd"), s);
        refused(List.of(s), out, "no science file among [" + SEG + ".sbd]");
    }

    @Test
    void aScienceFileWithoutItsFlightFile(@TempDir Path in, @TempDir Path out) throws Exception {
        Path t = in.resolve(SEG + ".tbd");
        Files.copy(DacFixtures.raw(SEG + ".tbd"), t);
        refused(List.of(t), out, SEG + ".tbd: its flight file (.sbd/.scd of " + SEG + ") is not among the files given");
    }

    @Test
    void aDiveThatNeverTurns(@TempDir Path in, @TempDir Path out) throws Exception {
        int p = column("sci_water_pressure");
        int t = column("sci_m_present_time");
        double[] start = {Double.NaN};
        refused(edited(in, (row, n) -> {
            if (!Double.isNaN(row[p])) {
                if (Double.isNaN(start[0])) {
                    start[0] = row[t];
                }
                row[p] = (row[t] - start[0]) / 1000; // ever deeper: 0.1 bar in 100 s
            }
        }), out, SEG + ".tbd: the pressure never turns");
    }

    @Test
    void aCtdThatGaveOnlyNaN(@TempDir Path in, @TempDir Path out) throws Exception {
        int temp = column("sci_water_temp");
        int cond = column("sci_water_cond");
        refused(edited(in, (row, n) -> {
            row[temp] = Double.NaN;
            row[cond] = Double.NaN;
        }), out, "the CTD gave no temperature or conductivity");
    }

    @Test
    void aClockThatStepsBack(@TempDir Path in, @TempDir Path out) throws Exception {
        int t = column("sci_m_present_time");
        refused(edited(in, (row, n) -> {
            if (n > 300) {
                row[t] -= 3600;
            }
        }), out, "the clock steps back at row");
    }

    @Test
    void anLz4BombIsStoppedWhereItsBoundIs(@TempDir Path in, @TempDir Path out) throws Exception {
        // a science file whose cycles never end: 4 MiB of "same as before" that compresses ~250:1
        List<SlocumSensor> sensors = List.of(new SlocumSensor("sci_m_present_time", "timestamp", 8),
                new SlocumSensor("sci_water_pressure", "bar", 4), new SlocumSensor("sci_water_temp", "degc", 4),
                new SlocumSensor("sci_water_cond", "s/m", 4));
        Map<String, String> tags = new LinkedHashMap<>();
        tags.put("full_filename", SEG);
        tags.put("filename_extension", "tbd");
        ByteArrayOutputStream plain = new ByteArrayOutputStream();
        SlocumEncoder e = SlocumEncoder.start(plain, tags, sensors);
        double[] row = {1.5e9, 1, 10, 3};
        for (int i = 0; i < 2_000_000; i++) {
            e.cycle(row);
        }
        byte[] compressed = Lz4Blocks.compress(plain.toByteArray(), 60_000);
        assertThat(compressed.length).isLessThan(plain.size() / 50);
        Path t = in.resolve(SEG + ".tcd");
        Files.write(t, compressed);
        Path s = in.resolve(SEG + ".sbd");
        Files.copy(DacFixtures.raw(SEG + ".sbd"), s);
        DacRun run = new DacRun(new SegmentReader(new SensorListCache(DacFixtures.cache()), 1 << 20), ProfileSplitter.defaults(),
                new ProfileWriter(Metadata.read(DacFixtures.meta()), QcConfig.none()), new ProfileChecker());
        long t0 = System.nanoTime();
        assertThatThrownBy(() -> run.run(List.of(s, t), out)).isInstanceOf(DacException.class)
                .hasMessageContaining(SEG + ".tcd: more than 1048576 bytes decompressed").hasMessageContaining("decompression bomb");
        assertThat((System.nanoTime() - t0) / 1e9).isLessThan(10);
        assertThat(out.toFile().list()).isEmpty();
    }

    @Test
    void metadataWithMissingAndWrongTypedFields(@TempDir Path dir) throws Exception {
        String good = Files.readString(DacFixtures.meta());
        Path m = dir.resolve("meta.json");
        Files.writeString(m, good.replace("\"title\": \"rosie_713 June 2019\",", "")
                .replace("\"wmo_id\": \"4802989\",\n    \"comment\"", "\"wmo_id\": 4802989,\n    \"comment\"")
                .replace("\"serial_number\": \"0123\"", "\"serial_number\": \"\""));
        assertThatThrownBy(() -> Metadata.read(m)).isInstanceOf(DacException.class)
                .hasMessageContaining("meta.json: 3 problems in the deployment metadata")
                .hasMessageContaining("global.title is missing")
                .hasMessageContaining("platform.wmo_id must be a string, found number 4802989")
                .hasMessageContaining("instrument_ctd.serial_number is empty");
        Files.writeString(m, "{\"global\": [], \"platform\": {}, \"instrument_ctd\": {}, \"extra\": 1}");
        assertThatThrownBy(() -> Metadata.read(m)).hasMessageContaining("'global' must be an object of attributes, found array")
                .hasMessageContaining("platform.id is missing").hasMessageContaining("unknown key 'extra'");
        Files.writeString(m, "{not json");
        assertThatThrownBy(() -> Metadata.read(m)).hasMessageContaining("meta.json: not JSON");
        Files.writeString(m, good.replace("\"trajectory\": \"rosie_713-20190615\"", "\"trajectory\": \"a-name-far-longer-than-twenty\""));
        assertThatThrownBy(() -> Metadata.read(m)).hasMessageContaining("trajectory must be a name of 1 to 20 characters");
        assertThat(Metadata.read(DacFixtures.meta()).platform()).containsEntry("wmo_id", "4802989");
    }
}
