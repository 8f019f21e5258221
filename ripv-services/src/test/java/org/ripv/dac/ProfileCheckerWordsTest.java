package org.ripv.dac;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The checker counts flag_meanings' words without a regex; it must count as {@code trim().split("\\s+")} did. */
class ProfileCheckerWordsTest {
    @Test
    void countsWordsAsSplitDid() {
        for (String s : new String[] {"GOOD NOT_EVALUATED SUSPECT FAIL MISSING", "", " ", "a", " a ", "a  b\tc\n", "\u0001a b\u0001",
                "no_qc_performed good_data probably_good_data bad_data_that_are_potentially_correctable bad_data value_changed"}) {
            assertThat(ProfileChecker.words(s)).as("'%s'", s).isEqualTo(s.trim().split("\\s+").length);
        }
        Random r = new Random(37);
        char[] alphabet = {'a', 'b', ' ', '\t', '\n', '\r', '\f', '\u000B', '\u0001', '_'};
        for (int k = 0; k < 10_000; k++) {
            char[] c = new char[r.nextInt(12)];
            for (int i = 0; i < c.length; i++) {
                c[i] = alphabet[r.nextInt(alphabet.length)];
            }
            String s = new String(c);
            assertThat(ProfileChecker.words(s)).as("'%s'", s).isEqualTo(s.trim().split("\\s+").length);
        }
    }
}
