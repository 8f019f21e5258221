package org.ripv.server.plans;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Collections;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Saved versions of a plan file (kept across a restart, marked sent, bounded) and the line diff between two. */
class PlanVersionsTest {
    static final String M = "<SerialPortServer>::<shore>ru29";

    @TempDir
    Path dir;

    @Test
    void everySaveIsAVersionWithWhoAndWhenAndTheSentOnesAreMarked() throws Exception {
        PlanVersions v = new PlanVersions(dir);
        v.save(M, "goto_l11.ma", "alice", "a\nb\n".getBytes(StandardCharsets.US_ASCII), "s1");
        v.save(M, "GOTO_L11.MA", "bob", "a\nc\n".getBytes(StandardCharsets.US_ASCII), "s2");
        v.sent(M, "s1", "as goto_l10.ma, change 4");
        PlanVersions again = new PlanVersions(dir);
        List<PlanVersions.Version> all = again.list(M, "goto_l11.ma");
        assertThat(all).extracting(PlanVersions.Version::n).containsExactly(1, 2);
        assertThat(all).extracting(PlanVersions.Version::user).containsExactly("alice", "bob");
        assertThat(all.get(0).sent()).isEqualTo("as goto_l10.ma, change 4");
        assertThat(all.get(1).sent()).isEmpty();
        assertThat(again.lastSentBefore(M, "goto_l11.ma", 2)).get().extracting(PlanVersions.Version::n).isEqualTo(1);
        assertThat(again.lastSentBefore(M, "goto_l11.ma", 1)).isEmpty();
        assertThat(new String(again.bytes(M, "goto_l11.ma", 2), StandardCharsets.US_ASCII)).isEqualTo("a\nc\n");
        assertThat(again.list(M, "goto_l12.ma")).isEmpty();
    }

    @Test
    void onlyTheNewestVersionsAreKept() throws Exception {
        PlanVersions v = new PlanVersions(dir);
        for (int i = 0; i < PlanVersions.KEEP + 5; i++) {
            v.save(M, "goto_l11.ma", "alice", new byte[] {(byte) 'a'}, "s" + i);
        }
        List<PlanVersions.Version> all = v.list(M, "goto_l11.ma");
        assertThat(all).hasSize(PlanVersions.KEEP);
        assertThat(all.get(0).n()).isEqualTo(6);
    }

    @Test
    void aMovedWaypointIsOneLineOutAndOneIn() {
        List<String> old = List.of("behavior_name=goto_list", "<start:waypoints>", "-7040.1200\t4121.5000", "-7035.8000\t4118.2500",
                "<end:waypoints>");
        List<String> now = List.of("behavior_name=goto_list", "<start:waypoints>", "-7040.1200\t4121.5000", "-7030.0000\t4110.0000",
                "<end:waypoints>");
        assertThat(LineDiff.diff(old, now)).containsExactly("  behavior_name=goto_list", "  <start:waypoints>",
                "  -7040.1200\t4121.5000", "- -7035.8000\t4118.2500", "+ -7030.0000\t4110.0000", "  <end:waypoints>");
        assertThat(LineDiff.diff(List.of("a", "b"), List.of("b", "c"))).containsExactly("- a", "  b", "+ c");
    }

    @Test
    void filesTooLongToCompareAreSaidToBe() {
        List<String> a = Collections.nCopies(3000, "x");
        List<String> b = Collections.nCopies(3000, "y");
        assertThat(LineDiff.diff(a, b)).hasSize(2).last().asString().contains("too long to compare");
    }
}
