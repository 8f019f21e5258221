package org.ripv.services.slocum;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.launch.Launchers;
import org.ripv.services.ingest.Lz4Blocks;
import org.ripv.services.ingest.SlocumData;
import picocli.CommandLine;

/** {@code ripv slocum decode}: dbd2asc's output for the shared files, --sensors, --merge, and the errors. */
class SlocumCommandTest {
    @TempDir
    Path tmp;
    final StringWriter out = new StringWriter();
    final StringWriter err = new StringWriter();

    int run(String... args) {
        CommandLine cl = Launchers.commandLine(new SlocumCommand(), "ripv slocum");
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        return cl.execute(args);
    }

    static Path file(String name) {
        return SlocumData.dir().resolve("realtime_raw").resolve(name);
    }

    @Test
    void decodePrintsWhatDbd2ascPrintsForEachFile() throws Exception {
        String cac = SlocumData.dir().resolve("cac").toString();
        Path a = file("rosie_713-2019-166-0-157.sbd");
        Path b = file("rosie_713-2019-166-0-157.tbd");
        assertThat(run("decode", "--cache", cac, a.toString(), b.toString())).as(err.toString()).isZero();
        assertThat(out.toString()).isEqualTo(SlocumData.expected(a) + SlocumData.expected(b));

        // a compressed copy, named as the glider names it
        Path scd = tmp.resolve("rosie_713-2019-166-0-157.scd");
        Files.write(scd, Lz4Blocks.compress(Files.readAllBytes(a), 8192));
        out.getBuffer().setLength(0);
        assertThat(run("decode", "-c", cac, scd.toString())).as(err.toString()).isZero();
        assertThat(out.toString()).isEqualTo(SlocumData.expected(a));
    }

    @Test
    void sensorsPicksColumnsWithTheirValues() throws Exception {
        Path a = file("rosie_713-2019-166-0-157.sbd");
        assertThat(run("decode", "--cache", SlocumData.dir().resolve("cac").toString(), "--sensors", "m_present_time,M_DEPTH",
                a.toString())).as(err.toString()).isZero();
        List<String> got = out.toString().lines().toList();
        List<String> want = SlocumData.expected(a).lines().toList();
        List<String> names = Arrays.asList(want.get(14).split(" "));
        int depth = names.indexOf("m_depth");
        int time = names.indexOf("m_present_time");
        assertThat(got.get(14)).isEqualTo("m_depth m_present_time ");
        assertThat(got).hasSameSizeAs(want);
        for (int i = 17; i < want.size(); i++) {
            String[] w = want.get(i).split(" ");
            assertThat(got.get(i)).isEqualTo(w[depth] + " " + w[time] + " ");
        }
    }

    @Test
    void mergeGivesBothFilesRowsInTimeOrder() throws Exception {
        Path a = file("rosie_713-2019-166-0-157.sbd");
        Path b = file("rosie_713-2019-166-0-157.tbd");
        assertThat(run("decode", "--merge", "--cache", SlocumData.dir().resolve("cac").toString(), a.toString(), b.toString()))
                .as(err.toString()).isZero();
        List<String> got = out.toString().lines().toList();
        int rowsA = (int) SlocumData.expected(a).lines().count() - 17;
        int rowsB = (int) SlocumData.expected(b).lines().count() - 17;
        assertThat(got).hasSize(17 + rowsA + rowsB);
        List<String> names = Arrays.asList(got.get(14).split(" "));
        assertThat(names).hasSize(27 + 9).contains("m_depth", "sci_water_temp");
        int t = names.indexOf("m_present_time");
        int st = names.indexOf("sci_m_present_time");
        double last = 0;
        for (String row : got.subList(17, got.size())) {
            String[] v = row.split(" ");
            double time = Double.parseDouble(v[t].equals("NaN") ? v[st] : v[t]);
            assertThat(time).isGreaterThanOrEqualTo(last);
            last = time;
        }
        assertThat(run("decode", "--merge", a.toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--merge takes two files");
    }

    @Test
    void errorsSayWhatIsWrongAndWhatToDo() throws Exception {
        Path a = file("rosie_713-2019-166-0-157.sbd");
        assertThat(run("decode", a.toString())).isEqualTo(1);
        assertThat(err.toString()).contains("6b016a2e.cac").contains("--cache DIR");
        assertThat(run("decode", "--cache", SlocumData.dir().resolve("cac").toString(), "--sensors", "m_nothing", a.toString()))
                .isEqualTo(2);
        assertThat(err.toString()).contains("'m_nothing' is not a sensor of the file");
        Path junk = Files.writeString(tmp.resolve("junk.sbd"), "hello\n");
        assertThat(run("decode", junk.toString())).isEqualTo(1);
        assertThat(err.toString()).contains("junk.sbd: byte 0: not a Slocum binary file");
        assertThat(run("decode", tmp.resolve("none.sbd").toString())).isEqualTo(1);
        assertThat(err.toString()).contains("no such file");
        assertThat(run("--help")).isZero();
        assertThat(out.toString()).contains("decode");
    }
}
