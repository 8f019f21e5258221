package org.ripv.server.workflow;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Map;
import org.junit.jupiter.api.Test;

class DirListingTest {
    @Test
    void aPicoDosListingGivesNamesAndSizes() {
        Map<String, Long> files = DirListing.listing("""
                 Volume in drive C is GLIDER
                 Directory of C:\\

                01230000.SBD      20000  11-23-26  15:02
                MISSION1.LOG      10348  11-23-26  15:02
                STATE            <DIR>   11-23-26  15:02
                        6 file(s)        88447 bytes
                C:\\>
                """);
        assertThat(files).containsExactly(Map.entry("01230000.SBD", 20000L), Map.entry("MISSION1.LOG", 10348L));
        assertThat(DirListing.listing("HUGE.LOG 99999999999999999999999 11-23-26 15:02")).isEmpty();
        assertThat(DirListing.listing("")).isEmpty();
    }

    @Test
    void globsMatchWholeNamesIgnoringCase() {
        assertThat(DirListing.glob("*.SBD").matcher("01230000.sbd").matches()).isTrue();
        assertThat(DirListing.glob("*.SBD").matcher("01230000.SBDX").matches()).isFalse();
        assertThat(DirListing.glob("0123000?.DBD").matcher("01230007.DBD").matches()).isTrue();
        assertThat(DirListing.glob("0123000?.DBD").matcher("012300077.DBD").matches()).isFalse();
        assertThat(DirListing.glob("a+b(1).LOG").matcher("A+B(1).log").matches()).as("regex characters are literal").isTrue();
    }
}
