package org.ripv.dac;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.ingest.SensorListCache;

/**
 * rosie_713's segment 157 (.sbd + .tbd) through the whole pipeline: its dives and climbs, every
 * written value against what Teledyne's dbd2asc printed for the same cycle, the files read back
 * by Debian's {@code ncdump} and python3-netcdf4, and the DAC check.
 */
class DacProfilesTest {
    static final String SEG = "rosie_713-2019-166-0-157";

    DacRun.Result run(Path out) throws Exception {
        return new DacRun(new SegmentReader(new SensorListCache(DacFixtures.cache())), ProfileSplitter.defaults(),
                new ProfileWriter(Metadata.read(DacFixtures.meta()), QcConfig.read(DacFixtures.qc())), new ProfileChecker())
                .run(List.of(DacFixtures.raw(SEG + ".tbd"), DacFixtures.raw(SEG + ".sbd")), out);
    }

    @Test
    void fiveYosMakeTenProfilesWhoseValuesAreDbd2ascs(@TempDir Path out) throws Exception {
        DacRun.Result r = run(out);
        assertThat(r.allPassed()).as(String.join("\n", r.lines())).isTrue();
        assertThat(r.written()).hasSize(10);
        assertThat(r.lines()).extracting(l -> l.split(",")[0].split(": ")[1])
                .containsExactly("dive", "climb", "dive", "climb", "dive", "climb", "dive", "climb", "dive", "climb");
        assertThat(out.toFile().list()).allMatch(n -> n.matches("rosie_713_20190620T\\d{6}Z_rt\\.nc"));

        // the expected science rows with a pressure, by time
        List<String> names = new ArrayList<>();
        List<double[]> rows = DacFixtures.rows(DacFixtures.shared().resolve("expected/" + SEG + ".tbd.dbd2asc.txt"), names);
        int ti = names.indexOf("sci_m_present_time"), pi = names.indexOf("sci_water_pressure"),
                tei = names.indexOf("sci_water_temp"), ci = names.indexOf("sci_water_cond");
        TreeMap<Double, double[]> byTime = new TreeMap<>();
        for (double[] row : rows) {
            if (!Double.isNaN(row[pi])) {
                byTime.put(row[ti], row);
            }
        }

        String py = """
                import json, sys, netCDF4
                out = {}
                for f in sys.argv[1:]:
                    d = netCDF4.Dataset(f)
                    d.set_auto_mask(False)
                    out[f] = {v: d[v][:].tolist() for v in ['time', 'pressure', 'temperature', 'conductivity', 'salinity', 'density', 'depth', 'lat', 'lon', 'profile_id', 'profile_time', 'u', 'v']}
                    out[f]['format'] = d.file_format
                    out[f]['trajectory'] = netCDF4.chartostring(d['trajectory'][:]).tolist()
                    out[f]['qc'] = d['qartod_temperature_primary_flag'][:].tolist()
                    out[f]['temperature_qc'] = d['temperature_qc'][:].tolist()
                print(json.dumps(out))
                """;
        Path script = out.resolve("read.py");
        Files.writeString(script, py);
        List<String> cmd = new ArrayList<>(List.of(Files.exists(Path.of("/usr/bin/python3")) ? "/usr/bin/python3" : "python3", script.toString()));
        r.written().forEach(f -> cmd.add(f.toString()));
        JsonNode files = new ObjectMapper().readTree(DacFixtures.run(out, cmd.toArray(String[]::new)));
        int samples = 0;
        double lastTime = 0;
        int lastId = 0;
        for (Path f : r.written()) {
            JsonNode d = files.get(f.toString());
            assertThat(d.get("format").asText()).isEqualTo("NETCDF3_CLASSIC");
            assertThat(d.get("trajectory").asText()).isEqualTo("rosie_713-20190615");
            assertThat(d.get("profile_id").asInt()).isGreaterThan(lastId);
            lastId = d.get("profile_id").asInt();
            for (int i = 0; i < d.get("time").size(); i++) {
                double t = d.get("time").get(i).asDouble();
                assertThat(t).as("time strictly increasing across files").isGreaterThan(lastTime);
                lastTime = t;
                // dbd2asc prints a time with 15 significant digits
                Map.Entry<Double, double[]> near = byTime.ceilingEntry(t - 1e-4);
                double[] want = near != null && Math.abs(near.getKey() - t) < 1e-4 ? near.getValue() : null;
                assertThat(want).as("a dbd2asc row at %s", t).isNotNull();
                // dbd2asc prints floats with %g: six significant digits
                assertThat(d.get("pressure").get(i).asDouble() / 10).isCloseTo(want[pi], within(Math.abs(want[pi]) * 5e-6 + 5e-7));
                assertThat(d.get("temperature").get(i).asDouble()).isCloseTo(want[tei], within(Math.abs(want[tei]) * 5e-6));
                assertThat(d.get("conductivity").get(i).asDouble()).isCloseTo(want[ci], within(Math.abs(want[ci]) * 5e-6));
                double p = d.get("pressure").get(i).asDouble();
                double lat = d.get("lat").get(i).asDouble();
                assertThat(lat).isBetween(51.0, 52.0);
                assertThat(d.get("depth").get(i).asDouble()).isCloseTo(-Gsw.zFromP(p, lat), within(1e-9));
                double sp = Gsw.spFromC(d.get("conductivity").get(i).asDouble() * 10, d.get("temperature").get(i).asDouble(), p);
                assertThat(d.get("salinity").get(i).asDouble()).isCloseTo(sp, within(1e-9)).isBetween(28.0, 35.0);
                assertThat(d.get("density").get(i).asDouble()).isBetween(1020.0, 1028.0);
                assertThat(d.get("qc").get(i).asInt()).isIn(1, 2, 3, 4, 9);
                samples++;
            }
            assertThat(d.get("u").asDouble()).isCloseTo(0.0373244695365429, within(1e-12));
        }
        // the profiles hold the samples between the first and the last turning point, each once
        assertThat(samples).isBetween(200, byTime.size());
    }

    @Test
    void everyTemplateVariableAndAttributeIsInTheFileAsNcdumpShowsIt(@TempDir Path out) throws Exception {
        DacRun.Result r = run(out);
        String header = DacFixtures.run(out, "ncdump", "-h", r.written().get(0).toString());
        assertThat(header).contains("time = UNLIMITED ; // (24 currently)").contains("traj_strlen = 20 ;");
        for (CdlTemplate.Var v : CdlTemplate.v2().variables()) {
            assertThat(header).contains("\t" + v.type() + " " + v.name() + (v.dims().isEmpty() ? " ;" : "(" + String.join(", ", v.dims()) + ") ;"));
            for (String a : v.attributes().keySet()) {
                assertThat(header).as(v.name() + ":" + a).contains("\t\t" + v.name() + ":" + a + " = ");
            }
        }
        for (String g : CdlTemplate.v2().globals().keySet()) {
            assertThat(header).contains("\t\t:" + g + " = ");
        }
        assertThat(header).contains("pressure:valid_min = 0. ;").contains("platform:wmo_id = \"4802989\" ;")
                .contains("instrument_ctd:serial_number = \"0123\" ;").contains(":title = \"rosie_713 June 2019\" ;")
                .contains("byte qartod_temperature_gross_range_flag(time) ;").contains("byte qartod_temperature_spike_flag(time) ;")
                .contains("byte qartod_temperature_rate_of_change_flag(time) ;").contains("byte qartod_temperature_flat_line_flag(time) ;")
                .contains("byte qartod_temperature_primary_flag(time) ;")
                .contains("temperature:ancillary_variables = \"temperature_qc qartod_temperature_gross_range_flag");
    }

    @Test
    void theCheckerFailsTheTemplatesOwnEmptyFileAndPassesOurs(@TempDir Path out) throws Exception {
        Path empty = out.resolve("empty.nc");
        DacFixtures.run(out, "ncgen", "-o", empty.toString(), DacFixtures.shared().resolve("../dac/IOOS_Glider_NetCDF_v2.0.cdl").normalize().toString());
        ProfileChecker.Report bad = new ProfileChecker().check(empty);
        assertThat(bad.passed()).isFalse();
        assertThat(String.join("\n", bad.failures())).contains("pressure:valid_min is int, not the variable's double");
        DacRun.Result r = run(out);
        ProfileChecker.Report good = new ProfileChecker().check(r.written().get(3));
        assertThat(good.failures()).isEmpty();
    }

    @Test
    void theDelayedModeFilesOfTheSameSegmentGiveDelayedFilesOfTheSameProfiles(@TempDir Path in, @TempDir Path out) throws Exception {
        SensorListCache cache = new SensorListCache(DacFixtures.cache());
        Path dbd = in.resolve(SEG + ".dbd");
        Path ebd = in.resolve(SEG + ".ebd");
        Files.write(dbd, org.ripv.services.ingest.SlocumEncoder.recode(Files.readAllBytes(DacFixtures.raw(SEG + ".sbd")), cache, "dbd", List.of(), (r, n) -> { }));
        Files.write(ebd, org.ripv.services.ingest.SlocumEncoder.recode(Files.readAllBytes(DacFixtures.raw(SEG + ".tbd")), cache, "ebd", List.of(), (r, n) -> { }));
        DacRun.Result delayed = new DacRun(new SegmentReader(cache), ProfileSplitter.defaults(),
                new ProfileWriter(Metadata.read(DacFixtures.meta()), QcConfig.none()), new ProfileChecker()).run(List.of(ebd, dbd), out);
        assertThat(delayed.allPassed()).isTrue();
        Path rtOut = Files.createDirectories(in.resolve("rt"));
        DacRun.Result rt = run(rtOut);
        assertThat(delayed.written()).extracting(f -> f.getFileName().toString())
                .containsExactlyElementsOf(rt.written().stream().map(f -> f.getFileName().toString().replace("_rt.nc", "_delayed.nc")).toList());
    }

    @Test
    void theSplitterIsPyglidersWithSettableLimits(@TempDir Path out) throws Exception {
        double[] p = new double[200];
        for (int i = 0; i < 200; i++) {
            p[i] = i < 100 ? i : 199 - i; // one dive, one climb
        }
        List<ProfileSplitter.Range> r = ProfileSplitter.defaults().split(p, "test");
        assertThat(r).extracting(ProfileSplitter.Range::direction).containsExactly(1, -1);
        assertThat(r.get(0).to() + 1).isEqualTo(r.get(1).from());
        assertThat(new ProfileSplitter(150, 14, 7).split(p, "test")).isEmpty();
        assertThat(new ProfileSplitter(10, 150, 7).split(p, "test")).isEmpty();
    }
}
