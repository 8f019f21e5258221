package org.ripv.dac;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * {@link Gsw} against the check values the TEOS-10 GSW toolbox publishes (GSW-C's
 * gsw_check_data, from gsw_data_v3_0.mat): three casts of 45 levels, each function within the
 * accuracy the toolbox itself demands of its ports ({@code *_ca}).
 */
class GswTest {
    static JsonNode check;

    @BeforeAll
    static void load() throws IOException {
        try (InputStream in = GswTest.class.getResourceAsStream("gsw-check-values.json")) {
            check = new ObjectMapper().readTree(in);
        }
    }

    static double at(String name, int i) {
        return check.get(name).get(i).asDouble();
    }

    static boolean given(int i, String... names) {
        for (String n : names) {
            if (at(n, i) > 1e80) {
                return false;
            }
        }
        return true;
    }

    static double lat(int i) {
        return check.get("lat_cast").get(i / 45).asDouble();
    }

    @Test
    void practicalSalinityFromConductivity() {
        int n = 0;
        for (int i = 0; i < 135; i++) {
            if (given(i, "c_from_sp", "t", "p", "sp_from_c")) {
                assertThat(Gsw.spFromC(at("c_from_sp", i), at("t", i), at("p", i)))
                        .as("level %d", i).isCloseTo(at("sp_from_c", i), within(check.get("sp_from_c_ca").asDouble()));
                n++;
            }
        }
        assertThat(n).isGreaterThan(90);
    }

    @Test
    void belowTwoTheHillExtensionMeetsPss78() {
        // continuity at SP = 2, and a fresh-water sample stays small and positive
        double c2 = 0.0;
        double lo = 0, hi = 10;
        for (int k = 0; k < 80; k++) {
            c2 = (lo + hi) / 2;
            if (Gsw.spFromC(c2, 10, 0) < 2) {
                lo = c2;
            } else {
                hi = c2;
            }
        }
        assertThat(Gsw.spFromC(c2 * (1 - 1e-9), 10, 0)).isCloseTo(2, within(1e-6));
        assertThat(Gsw.spFromC(0.05, 10, 0)).isBetween(0.0, 0.1);
        assertThat(Gsw.spFromC(-1, 10, 0)).isNaN();
        assertThat(Gsw.spFromC(Double.NaN, 10, 0)).isNaN();
    }

    @Test
    void referenceSalinityAndAbsoluteSalinity() {
        for (int i = 0; i < 135; i++) {
            if (given(i, "sp", "sr_from_sp", "sa_from_sp")) {
                assertThat(Gsw.srFromSp(at("sp", i))).isCloseTo(at("sr_from_sp", i), within(check.get("sr_from_sp_ca").asDouble()));
                assertThat(Gsw.saFromSp(at("sp", i), 0)).isEqualTo(Gsw.srFromSp(at("sp", i)));
                // the published SA differs from SR by the atlas's anomaly ratio: under 0.02 g/kg in the
                // open-ocean casts (the third cast is in the Baltic, which GSW treats apart)
                if (i < 90) {
                    assertThat(Gsw.saFromSp(at("sp", i), 0)).isCloseTo(at("sa_from_sp", i), within(0.02));
                }
                double saar = at("sa_from_sp", i) / (Gsw.UPS * at("sp", i)) - 1;
                assertThat(Gsw.saFromSp(at("sp", i), saar)).isCloseTo(at("sa_from_sp", i), within(check.get("sa_from_sp_ca").asDouble()));
            }
        }
    }

    @Test
    void conservativeTemperature() {
        int n = 0;
        for (int i = 0; i < 135; i++) {
            if (given(i, "sa", "t", "p", "ct_from_t")) {
                assertThat(Gsw.ctFromT(at("sa", i), at("t", i), at("p", i))).as("level %d", i)
                        .isCloseTo(at("ct_from_t", i), within(check.get("ct_from_t_ca").asDouble()));
                n++;
            }
        }
        assertThat(n).isGreaterThan(90);
    }

    @Test
    void density() {
        int n = 0;
        for (int i = 0; i < 135; i++) {
            if (given(i, "sa", "ct", "p", "rho")) {
                assertThat(Gsw.rho(at("sa", i), at("ct", i), at("p", i))).as("level %d", i)
                        .isCloseTo(at("rho", i), within(check.get("rho_ca").asDouble()));
                n++;
            }
        }
        assertThat(n).isGreaterThan(90);
    }

    @Test
    void heightFromPressure() {
        int n = 0;
        for (int i = 0; i < 135; i++) {
            if (given(i, "p", "z_from_p")) {
                assertThat(Gsw.zFromP(at("p", i), lat(i))).as("level %d", i)
                        .isCloseTo(at("z_from_p", i), within(check.get("z_from_p_ca").asDouble()));
                n++;
            }
        }
        assertThat(n).isGreaterThan(90);
    }
}
