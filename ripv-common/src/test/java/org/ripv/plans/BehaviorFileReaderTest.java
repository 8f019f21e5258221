package org.ripv.plans;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;

import org.junit.jupiter.api.Test;

class BehaviorFileReaderTest {
    private static PlanCheck resource(String name) throws IOException {
        try (InputStream in = BehaviorFileReaderTest.class.getResourceAsStream("/plans/" + name)) {
            return BehaviorFileReader.check(name, in, PlanLimits.DEFAULT);
        }
    }

    private static PlanCheck text(String text) {
        return BehaviorFileReader.check("goto_l10.ma", text.getBytes(StandardCharsets.ISO_8859_1), PlanLimits.DEFAULT);
    }

    private static List<String> problems(String text) {
        PlanCheck c = text(text);
        assertThat(c.ok()).as("refused").isFalse();
        return c.problems().stream().map(PlanProblem::toString).toList();
    }

    private static final String GOOD_HEAD = "behavior_name=goto_list\n<start:b_arg>\nb_arg: num_waypoints(nodim) 2\n<end:b_arg>\n<start:waypoints>\n";

    @Test
    void anSfmcWrittenFileReadsWithItsTabsAndComments() throws IOException {
        PlanCheck c = resource("sfmc_goto_l11.ma");
        assertThat(c.problems()).isEmpty();
        BehaviorFile f = c.file();
        assertThat(f.isGoto()).isTrue();
        assertThat(f.bargs()).extracting(BArg::name).containsExactly("num_legs_to_run", "start_when", "list_stop_when",
                "list_when_wpt_dist", "initial_wpt", "num_waypoints");
        assertThat(f.barg("start_when").orElseThrow().comment()).isEqualTo("BAW_IMMEDIATELY");
        assertThat(f.barg("list_when_wpt_dist").orElseThrow().value()).isEqualTo(100.0);
        assertThat(f.waypoints()).hasSize(5);
        Waypoint w0 = f.waypoints().get(0);
        assertThat(w0.n()).isZero();
        assertThat(w0.lon()).isCloseTo(-(70 + 40.12 / 60), org.assertj.core.data.Offset.offset(1e-9));
        assertThat(w0.lat()).isCloseTo(41 + 21.5 / 60, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(w0.line()).isEqualTo(14);
        assertThat(f.sha256()).hasSize(64);
    }

    @Test
    void aHandWrittenFileWithCrLfTabsHashesAfterValuesAndCommentedOutWaypoints() throws IOException {
        PlanCheck c = resource("handwritten_goto_l12.ma");
        assertThat(c.problems()).isEmpty();
        BehaviorFile f = c.file();
        assertThat(f.barg("initial_wpt").orElseThrow().text()).isEqualTo("-2");
        assertThat(f.barg("initial_wpt").orElseThrow().comment()).isEqualTo("closest");
        assertThat(f.barg("list_when_wpt_dist").orElseThrow().value()).isEqualTo(50.0);
        assertThat(f.waypoints()).extracting(Waypoint::n).containsExactly(0, 1, 2);
        assertThat(f.waypoints().get(0).comment()).isEqualTo("wpt 0 west corner");
        assertThat(f.waypoints().get(1).lat()).isCloseTo(41 + 19.9 / 60, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(f.waypoints().get(2).comment()).isEmpty();
    }

    @Test
    void aScriptGeneratedFileAndAToolsFileWithADegreeSignInAComment() throws IOException {
        assertThat(resource("script_goto_l13.ma").file().waypoints()).hasSize(4);
        BehaviorFile f = resource("generated_goto_l14.ma").file();
        assertThat(f.waypoints()).hasSize(3);
        assertThat(f.waypoints().get(0).lon()).isCloseTo(-73.0, org.assertj.core.data.Offset.offset(1e-9));
        // east and south: signs in front, zero-padded degrees
        assertThat(f.waypoints().get(2).lon()).isCloseTo(138 + 10.5 / 60, org.assertj.core.data.Offset.offset(1e-9));
        assertThat(f.waypoints().get(2).lat()).isCloseTo(-(33 + 45.25 / 60), org.assertj.core.data.Offset.offset(1e-9));
        assertThat(f.waypoints().get(1).comment()).isEqualTo("304  |  middle");
    }

    @Test
    void surfaceAndYoFilesHaveBArgsAndNoWaypoints() throws IOException {
        BehaviorFile s = resource("surfac06.ma").file();
        assertThat(s.behavior()).isEqualTo("surface");
        assertThat(s.isGoto()).isFalse();
        assertThat(s.barg("c_pitch_value").orElseThrow().units()).isEqualTo("X");
        BehaviorFile y = resource("yo10.ma").file();
        assertThat(y.barg("d_target_depth").orElseThrow().value()).isEqualTo(30.0);
        assertThat(y.bargs()).hasSize(10);
    }

    @Test
    void theShippedSampleReads() throws IOException {
        java.nio.file.Path sample = java.nio.file.Path.of("..", "docs", "samples", "goto_l10.ma");
        PlanCheck c = BehaviorFileReader.check("goto_l10.ma", java.nio.file.Files.readAllBytes(sample), PlanLimits.DEFAULT);
        assertThat(c.problems()).isEmpty();
        assertThat(c.file().waypoints()).hasSize(4);
    }

    @Test
    void coordinatesOutOfRangeAndMinutesOfSixtyAreRefusedWithTheirLines() {
        assertThat(problems(GOOD_HEAD + "-7032.188 9100.000\n-7060.000 4137.000\n<end:waypoints>\n")).containsExactly(
                "goto_l10.ma:6: latitude '9100.000' is 91.00000°, over 90°",
                "goto_l10.ma:7: longitude '-7060.000' has 60 minutes: minutes must be under 60 (DDMM.mmmm)");
        assertThat(problems(GOOD_HEAD + "-18030.000 4137.000\n-7000 4159.99999\n<end:waypoints>\n"))
                .containsExactly("goto_l10.ma:6: longitude '-18030.000' is 180.50000°, over 180°");
        assertThat(problems(GOOD_HEAD + "-7032.188 4137.0\n-7032.188 4160\n<end:waypoints>\n"))
                .containsExactly("goto_l10.ma:7: latitude '4160' has 60 minutes: minutes must be under 60 (DDMM.mmmm)");
        assertThat(problems(GOOD_HEAD + "-7032.188 1e3\n-7032.188 4137\n<end:waypoints>\n"))
                .containsExactly("goto_l10.ma:6: latitude '1e3' is not a number in DDMM.mmmm");
    }

    @Test
    void aCountThatDoesNotMatchTheListIsRefused() {
        assertThat(problems(GOOD_HEAD + "-7032.188 4137.0\n#-7030 4136\n<end:waypoints>\n")).containsExactly(
                "goto_l10.ma:3: num_waypoints is 2 but the list has 1 waypoint(s) (from line 6)");
        assertThat(problems("behavior_name=goto_list\n<start:b_arg>\nb_arg: start_when(enum) 0\n<end:b_arg>\n<start:waypoints>\n"
                + "-7032.188 4137.0\n<end:waypoints>\n"))
                .containsExactly("goto_l10.ma:2: no b_arg num_waypoints(nodim): the glider reads that many waypoints (0 without it)");
    }

    @Test
    void missingEndTagsAndStrayTagsAreRefused() {
        assertThat(problems(GOOD_HEAD + "-7032.188 4137.0\n-7030 4136\n")).containsExactly(
                "goto_l10.ma:5: <start:waypoints> has no <end:waypoints> (the file ends at line 7)");
        assertThat(problems("behavior_name=yo\n<start:b_arg>\nb_arg: d_target_depth(m) 30\n<start:waypoints>\n<end:b_arg>\n"))
                .containsExactly("goto_l10.ma:4: <start:waypoints> inside the block started at line 2 (no <end:b_arg> before it)");
        assertThat(problems("behavior_name=yo\n<start:b_args>\n")).first().asString()
                .startsWith("goto_l10.ma:2: unknown tag '<start:b_args>'");
    }

    @Test
    void unknownBehavioursAndUnitsAndJunkAfterAValueAreRefused() {
        assertThat(problems("behavior_name=goto_lsit\n")).first().asString()
                .startsWith("goto_l10.ma:1: unknown behaviour 'goto_lsit': the glider knows abend, climb_to,");
        assertThat(problems("behavior_name=yo\n<start:b_arg>\nb_arg: d_target_depth(fathoms) 30\n<end:b_arg>\n")).first().asString()
                .startsWith("goto_l10.ma:3: unknown unit 'fathoms' of b_arg d_target_depth");
        assertThat(problems("behavior_name=yo\n<start:b_arg>\nb_arg: d_target_depth(m) 30 40\n<end:b_arg>\n"))
                .containsExactly("goto_l10.ma:3: b_arg d_target_depth: '40' after the value; start a comment with #");
        assertThat(problems("behavior_name=yo\n<start:b_arg>\nb_arg: d_target_depth(m) deep\nb_arg: d_target_depth(m) 3\n<end:b_arg>\n"))
                .containsExactly("goto_l10.ma:3: b_arg d_target_depth value 'deep' is not a number");
        assertThat(problems("behavior_name=yo\n<start:b_arg>\nb_arg: d_target_depth(m) 3\nB_ARG: D_TARGET_DEPTH(m) 4\n<end:b_arg>\n"))
                .containsExactly("goto_l10.ma:4: 'B_ARG: D_TARGET_DEPTH(m) 4' is not b_arg: NAME(UNITS) VALUE");
        assertThat(problems("behavior_name=yo\n<start:b_arg>\nb_arg: d_target_depth(m) 3\nb_arg: D_target_depth(m) 4\n<end:b_arg>\n"))
                .containsExactly("goto_l10.ma:4: b_arg D_target_depth is set again (first at line 3)");
        assertThat(problems("# no name\n<start:b_arg>\n<end:b_arg>\n")).first().asString()
                .isEqualTo("goto_l10.ma:2: behavior_name= must come before <start:b_arg>");
        assertThat(problems("behavior_name=yo\nsensor: u_foo(m) 3\n")).first().asString()
                .startsWith("goto_l10.ma:2: 'sensor: u_foo(m) 3' outside a block");
    }

    @Test
    void moreWaypointsThanTheFirmwareTakesAreRefused() {
        StringBuilder b = new StringBuilder("behavior_name=goto_list\n<start:b_arg>\nb_arg: num_waypoints(nodim) 9\n<end:b_arg>\n<start:waypoints>\n");
        for (int i = 0; i < 9; i++) {
            b.append("-7032.188 4137.0\n");
        }
        b.append("<end:waypoints>\n");
        assertThat(problems(b.toString())).containsExactly(
                "goto_l10.ma:14: more than 8 waypoints: the firmware takes at most 8 (goto_list's num_waypoints)",
                "goto_l10.ma:3: num_waypoints is 9: the firmware takes at most 8");
        PlanCheck bigger = BehaviorFileReader.check("goto_l10.ma", b.toString().getBytes(StandardCharsets.US_ASCII),
                PlanLimits.DEFAULT.withMaxWaypoints(16));
        assertThat(bigger.ok()).isTrue();
        assertThat(problems(GOOD_HEAD.replace("b_arg: num", "b_arg: initial_wpt(enum) 2\nb_arg: num")
                + "-7032.188 4137.0\n-7032.188 4137.0\n<end:waypoints>\n")).containsExactly(
                "goto_l10.ma:3: initial_wpt 2 is not a waypoint of the list: 0 to 1, -1 (one after the last achieved) or -2 (the closest)");
    }

    @Test
    void controlBytesAndNonAsciiOutsideCommentsAreRefusedWithTheirLines() {
        assertThat(problems(GOOD_HEAD + "-7032.188 4137.0\u0007\n-7032.188 4137.0\n<end:waypoints>\n")).containsExactly(
                "goto_l10.ma:6: control byte 0x07 at column 17: a behaviour file is plain text",
                "goto_l10.ma:3: num_waypoints is 2 but the list has 1 waypoint(s) (from line 7)");
        assertThat(problems("behavior_name=yo\n<start:b_arg>\nb_arg: d_t\u00e9rget_depth(m) 3\n<end:b_arg>\n"))
                .containsExactly("goto_l10.ma:3: non-ASCII byte 0xE9 at column 11 outside a comment: the glider reads ASCII");
        assertThat(text("behavior_name=yo # d\u00e9j\u00e0 vu\n<start:b_arg>\n<end:b_arg>\n").ok()).isTrue();
    }

    @Test
    void aMegabyteLineIsRefusedWithItsLineAndNotKept() {
        byte[] line = new byte[1 << 20];
        java.util.Arrays.fill(line, (byte) '7');
        byte[] head = GOOD_HEAD.getBytes(StandardCharsets.US_ASCII);
        byte[] all = new byte[head.length + line.length];
        System.arraycopy(head, 0, all, 0, head.length);
        System.arraycopy(line, 0, all, head.length, line.length);
        PlanCheck c = BehaviorFileReader.check("goto_l10.ma", all, new PlanLimits(8, 4 << 20, 1024, 50));
        assertThat(c.problemText()).isEqualTo("goto_l10.ma:6: the line is longer than 1024 characters; nothing more was read");
    }

    @Test
    void aBillionWaypointsCostsBoundedMemoryAndTime() throws IOException {
        // an endless stream of waypoints: the reader stops at the file limit, having kept at most 9
        byte[] wpt = "-7032.188 4137.0\n".getBytes(StandardCharsets.US_ASCII);
        long[] served = {0};
        InputStream endless = new InputStream() {
            int at;

            @Override
            public int read() {
                served[0]++;
                int b = wpt[at];
                at = (at + 1) % wpt.length;
                return b;
            }

            @Override
            public int read(byte[] b, int off, int len) {
                for (int i = 0; i < len; i++) {
                    b[off + i] = (byte) read();
                }
                return len;
            }
        };
        PlanCheck c = BehaviorFileReader.check("goto_l10.ma", new java.io.SequenceInputStream(
                new java.io.ByteArrayInputStream(GOOD_HEAD.getBytes(StandardCharsets.US_ASCII)), endless), PlanLimits.DEFAULT);
        assertThat(served[0]).isLessThan(300_000);
        assertThat(c.problems()).extracting(PlanProblem::toString).containsExactly(
                "goto_l10.ma:14: more than 8 waypoints: the firmware takes at most 8 (goto_list's num_waypoints)",
                c.problems().get(1).toString());
        assertThat(c.problems().get(1).reason()).startsWith("the file is longer than 262144 bytes");
    }

    @Test
    void tooManyProblemsStopTheRead() {
        StringBuilder b = new StringBuilder("behavior_name=yo\n");
        for (int i = 0; i < 1000; i++) {
            b.append("junk\n");
        }
        PlanCheck c = text(b.toString());
        assertThat(c.problems()).hasSize(51);
        assertThat(c.problems().get(50).reason()).isEqualTo("more problems follow; fix these first");
    }
}
