package org.ripv.plans;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PlanMainTest {
    @TempDir
    Path dir;

    private record Run(int exit, String out, String err) {}

    private static Run run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int exit = PlanMain.run(args, new PrintWriter(out, true), new PrintWriter(err, true));
        return new Run(exit, out.toString(), err.toString());
    }

    private Path write(String name, String text) throws Exception {
        Path p = dir.resolve(name);
        Files.writeString(p, text, StandardCharsets.ISO_8859_1);
        return p;
    }

    @Test
    void aGoodFilePrintsItsTableAndExitsZero() throws Exception {
        Path good = write("goto_l10.ma", "behavior_name=goto_list\n<start:b_arg>\nb_arg: num_waypoints(nodim) 2 # two\n"
                + "<end:b_arg>\n<start:waypoints>\n-7032.188 4137.994 # start\n-7030 4136\n<end:waypoints>\n");
        Run r = run("check", good.toString());
        assertThat(r.exit()).as(r.err()).isZero();
        assertThat(r.out()).startsWith("goto_l10.ma: goto_list, 2 waypoint(s), 1 b_arg(s), sha256 ")
                .contains("   n         lat          lon  comment")
                .contains("   0    41.63323    -70.53647  start")
                .contains("   1    41.60000    -70.50000")
                .contains("b_args:\n  num_waypoints(nodim)  2  # two");
        assertThat(r.err()).isEmpty();
    }

    @Test
    void aRefusedFilePrintsFileLineReasonOnStandardErrorAndExitsOne() throws Exception {
        Path bad = write("goto_l11.ma", "behavior_name=goto_list\n<start:b_arg>\nb_arg: num_waypoints(nodim) 1\n"
                + "<end:b_arg>\n<start:waypoints>\n-7032.188 9137.994\n");
        Path good = write("yo10.ma", "behavior_name=yo\n<start:b_arg>\nb_arg: d_target_depth(m) 30\n<end:b_arg>\n");
        Run r = run("check", bad.toString(), good.toString());
        assertThat(r.exit()).isEqualTo(1);
        assertThat(r.err()).isEqualTo("goto_l11.ma:6: latitude '9137.994' is 91.63323°, over 90°\n"
                + "goto_l11.ma:5: <start:waypoints> has no <end:waypoints> (the file ends at line 6)\n"
                + "goto_l11.ma: refused, 2 problem(s)\n");
        assertThat(r.out()).startsWith("yo10.ma: yo, 1 b_arg(s)");
    }

    @Test
    void aMissingFileAndBadOptionsAreErrors() throws Exception {
        Run missing = run("check", dir.resolve("nope.ma").toString());
        assertThat(missing.exit()).isEqualTo(1);
        assertThat(missing.err()).startsWith("Error: cannot read ").contains("nope.ma");
        Run none = run("check");
        assertThat(none.exit()).isEqualTo(2);
        assertThat(none.err()).contains("Missing required parameter: 'FILE'");
        Run zero = run("check", "--max-waypoints", "0", "x.ma");
        assertThat(zero.exit()).isEqualTo(2);
        assertThat(zero.err()).contains("--max-waypoints: the waypoint limit is 1 to 10000, not 0");
        Run help = run("check", "--help");
        assertThat(help.exit()).isZero();
        assertThat(help.out()).contains("Usage: ripv plan check").contains("--max-waypoints");
    }
}
