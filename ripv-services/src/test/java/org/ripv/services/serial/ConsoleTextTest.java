package org.ripv.services.serial;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The pieces of the console: GPS lines, line cutting, the rate, and the simulator's positions. */
class ConsoleTextTest {

    @Test
    void gpsLinesInDegreesAndMinutesBecomeDecimalDegrees() {
        GpsFix fix = GpsFix.parse("GPS Location:  4137.994 N -7032.188 E measured     26.0 secs ago").orElseThrow();
        assertThat(fix.lat()).isCloseTo(41.633233, within(1e-6));
        assertThat(fix.lon()).isCloseTo(-70.536467, within(1e-6));
        fix = GpsFix.parse("GPS Location: 4137.994 S 7032.188 W measured 1 secs ago").orElseThrow();
        assertThat(fix.lat()).isCloseTo(-41.633233, within(1e-6));
        assertThat(fix.lon()).isCloseTo(-70.536467, within(1e-6));
        fix = GpsFix.parse("GPS Location: -3352.500 N 15112.000 E measured 3 secs ago").orElseThrow();
        assertThat(fix.lat()).isCloseTo(-33.875, within(1e-9));
        assertThat(fix.lon()).isCloseTo(151.2, within(1e-9));
        assertThat(GpsFix.parse("GPS Location: 0005.000 N -00030.000 E").orElseThrow().lon()).isCloseTo(-0.5, within(1e-9));
        // Slocum's no-fix value, minutes of 60 or more, and other lines are no position
        assertThat(GpsFix.parse("GPS Location:  69696969.000 N 69696969.000 E measured 1e+308 secs ago")).isEmpty();
        assertThat(GpsFix.parse("GPS Location: 4175.000 N 7032.188 E")).isEmpty();
        assertThat(GpsFix.parse("GPS Invalid : 4137.994 N -7032.188 E measured 26.0 secs ago")).isEmpty();
        assertThat(GpsFix.parse("DR  Location:  4137.990 N -7032.190 E")).isEmpty();
    }

    private static List<String> feed(LineAssembler a, String... chunks) {
        List<String> out = new ArrayList<>();
        for (String c : chunks) {
            byte[] b = c.getBytes(StandardCharsets.ISO_8859_1);
            a.feed(b, 0, b.length, out::add);
        }
        return out;
    }

    @Test
    void linesEndAtCrLfOrEitherAndAreMadePrintable() {
        LineAssembler a = new LineAssembler(1024);
        assertThat(feed(a, "one\r\ntw", "o\rthree\nfour\r", "\nfive")).containsExactly("one", "two", "three", "four");
        List<String> rest = new ArrayList<>();
        a.flush(rest::add);
        assertThat(rest).containsExactly("five");
        assertThat(feed(new LineAssembler(1024), "a\tb\u0000c\u0007d\u00ffe\r\n")).containsExactly("a bc\uFFFDd\uFFFDe");
        assertThat(feed(new LineAssembler(1024), "dirt\b \b\r\n\r\n\r\n   \r\n")).containsExactly("dir");
    }

    @Test
    void aLongLineIsCutAndTheRestCountedNotKept() {
        LineAssembler a = new LineAssembler(16);
        List<String> out = feed(a, "x".repeat(16), "y".repeat(100_000), "\r\nnext\r\n");
        assertThat(out).containsExactly("x".repeat(16) + " [line cut at 16 characters]",
                "[100000 more characters of that line dropped]", "next");
    }

    @Test
    void theRateAdmitsABurstThenItsRateAndCountsTheRest() {
        long t = 0;
        LineRate r = new LineRate(10, t);
        int admitted = 0;
        for (int i = 0; i < 100; i++) {
            admitted += r.admit(t) ? 1 : 0;
        }
        assertThat(admitted).isEqualTo(10);
        assertThat(r.takeSkipped()).isEqualTo(90);
        assertThat(r.takeSkipped()).isZero();
        t += 500_000_000L; // half a second: five more
        admitted = 0;
        for (int i = 0; i < 100; i++) {
            admitted += r.admit(t) ? 1 : 0;
        }
        assertThat(admitted).isEqualTo(5);
    }

    @Test
    void theSimulatorPrintsPositionsAsGlidersDoAndTheyParseBack() {
        assertThat(org.ripv.services.simulator.SimulatorPositions.format(41 + 37.994 / 60)).isEqualTo("4137.994");
        assertThat(org.ripv.services.simulator.SimulatorPositions.format(-(70 + 32.188 / 60))).isEqualTo("-7032.188");
        assertThat(org.ripv.services.simulator.SimulatorPositions.format(5.5)).isEqualTo("530.000");
        for (int call = 1; call < 50; call++) {
            double[] p = org.ripv.services.simulator.SimulatorPositions.position(call);
            String line = "GPS Location:  " + org.ripv.services.simulator.SimulatorPositions.format(p[0]) + " N "
                    + org.ripv.services.simulator.SimulatorPositions.format(p[1]) + " E measured 26.0 secs ago";
            GpsFix fix = GpsFix.parse(line).orElseThrow();
            assertThat(fix.lat()).isCloseTo(p[0], within(1e-5));
            assertThat(fix.lon()).isCloseTo(p[1], within(1e-5));
        }
    }
}
