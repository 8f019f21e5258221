package org.ripv.services.serial.ymodem;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class AskedNamesTest {
    private static FileHeader f(String name) {
        return new FileHeader(name, 1, 0, 0);
    }

    @Test
    void onlyAskedNamesAreKeptUnderTheOperatorsSpelling() {
        AskedNames.Verdict v = new AskedNames(List.of("mission1.log", "*.DBD")).check(
                List.of(f("MISSION1.LOG"), f("OVER"), f("01230000.DBD"), f("GLIDER.CFG"), f("Mission1.log")));
        assertThat(v.accepted()).extracting(AskedNames.Accepted::storedName)
                .containsExactly("mission1.log", "01230000.DBD");
        assertThat(v.warnings()).hasSize(3).anySatisfy(w -> assertThat(w).contains("'OVER', which was not asked for"))
                .anySatisfy(w -> assertThat(w).contains("'GLIDER.CFG'")).anySatisfy(w -> assertThat(w).contains("more than once"));
    }

    @Test
    void aPatternNeverMatchesAcrossADirectory() {
        AskedNames.Verdict v = new AskedNames(List.of("*")).check(List.of(f("A.LOG")));
        assertThat(v.accepted()).hasSize(1);
        assertThat(new AskedNames(List.of("A?.LOG")).storedName("AB.LOG")).isEqualTo("AB.LOG");
        assertThat(new AskedNames(List.of("A?.LOG")).storedName("ABC.LOG")).isNull();
        assertThat(new AskedNames(List.of("OVER")).storedName("MISSION1.LOG")).isNull();
    }
}
