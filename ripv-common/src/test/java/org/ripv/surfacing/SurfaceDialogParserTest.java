package org.ripv.surfacing;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

class SurfaceDialogParserTest {

    /** What a parser said, in order. */
    static final class Heard implements SurfaceDialogParser.Listener {
        final List<Surfacing> dialogs = new ArrayList<>();
        final List<Long> countdowns = new ArrayList<>();
        final List<Surfacing.Prompt> prompts = new ArrayList<>();

        @Override
        public void surfacing(Surfacing s) {
            dialogs.add(s);
        }

        @Override
        public void countdown(long seconds) {
            countdowns.add(seconds);
        }

        @Override
        public void prompt(Surfacing.Prompt p) {
            prompts.add(p);
        }
    }

    static String dialog(String name) throws IOException {
        try (InputStream in = SurfaceDialogParserTest.class.getResourceAsStream(name)) {
            return new String(in.readAllBytes(), StandardCharsets.ISO_8859_1);
        }
    }

    static Heard parse(String text) {
        Heard h = new Heard();
        SurfaceDialogParser p = new SurfaceDialogParser(h);
        p.feed(text);
        p.end();
        return h;
    }

    @Test
    void firmware7RoutineSurfacing() throws IOException {
        Heard h = parse(dialog("fw7-surface-interval.txt"));
        assertThat(h.dialogs).hasSize(1);
        Surfacing s = h.dialogs.get(0);
        assertThat(s.vehicle()).isEqualTo("unit_345");
        assertThat(s.because()).isEqualTo("Surface interval");
        assertThat(s.becauseText()).isEqualTo("Surface interval [behavior surface_2 start_when = 8]");
        assertThat(s.mission()).isEqualTo("sa_slope.mi");
        assertThat(s.missionNum()).isEqualTo("unit_345-2012-236-3-41 (0106.0041)");
        assertThat(s.vehicleTime()).isEqualTo(Instant.parse("2012-08-24T13:51:09Z"));
        assertThat(s.missionTime()).isEqualTo(170331L);
        assertThat(s.gps().lat()).isCloseTo(38 + 52.4498 / 60, within(1e-9));
        assertThat(s.gps().lon()).isCloseTo(-(74 + 20.1730 / 60), within(1e-9));
        assertThat(s.gps().ageSeconds()).isEqualTo(38.012);
        assertThat(s.gpsProblem()).isNull();
        assertThat(s.dr().lat()).isCloseTo(38 + 52.4211 / 60, within(1e-9));
        assertThat(s.sensors()).containsKeys("c_wpt_lat", "c_wpt_lon", "m_battery", "m_vacuum", "m_leakdetect_voltage",
                "m_coulomb_amphr_total", "m_water_vx", "m_water_vy");
        assertThat(s.value("m_battery")).isEqualTo(14.6134148573529);
        assertThat(s.sensors().get("m_vacuum").units()).isEqualTo("inHg");
        assertThat(s.sensors().get("m_water_vy").ageSeconds()).isEqualTo(1002.44);
        assertThat(s.devices().oddities()).isEqualTo(new Surfacing.Counts(0, 0, 1));
        assertThat(s.aborts().total()).isZero();
        assertThat(s.aborts().cause()).isNull();
        assertThat(s.end()).isEqualTo(Surfacing.End.COUNTDOWN);
        assertThat(s.countdown()).isEqualTo(10L);
        assertThat(s.unknown()).containsExactly("Hit Control-R to RESUME the mission, or Control-C to abort it");
        assertThat(h.countdowns).containsExactly(10L, 0L);
    }

    @Test
    void firmware8AbortWithItsHistoryAndThePrompt() throws IOException {
        Heard h = parse(dialog("fw8-abort-overdepth.txt"));
        assertThat(h.dialogs).hasSize(1);
        Surfacing s = h.dialogs.get(0);
        assertThat(s.because()).isEqualTo("Abort");
        assertThat(s.gps().lat()).isCloseTo(41.63323, within(1e-5));
        assertThat(s.gps().lon()).isCloseTo(-70.53647, within(1e-5));
        assertThat(s.gps().ageSeconds()).isEqualTo(26.015);
        Surfacing.AbortHistory a = s.aborts();
        assertThat(a.total()).isEqualTo(3L);
        assertThat(a.cause()).isEqualTo("MS_ABORT_OVERDEPTH");
        assertThat(a.details()).isEqualTo("dive_to: depth 1012.3 > max depth 1000.0");
        assertThat(a.time()).isEqualTo("2026-11-23T13:02:41");
        assertThat(a.segment()).isEqualTo("ru29-2026-327-2-4 (0031.0004)");
        assertThat(a.mission()).isEqualTo("deep.mi");
        assertThat(s.devices().errors()).isEqualTo(new Surfacing.Counts(2, 0, 0));
        assertThat(s.devices().warnings()).isEqualTo(new Surfacing.Counts(5, 1, 0));
        assertThat(s.prompt()).isEqualTo(new Surfacing.Prompt("GliderDOS", "A", 8));
        assertThat(s.end()).isEqualTo(Surfacing.End.PROMPT);
        assertThat(s.value("m_leakdetect_voltage_forward")).isEqualTo(2.49);
        assertThat(s.unknown()).singleElement().asString().startsWith("Waypoint: (-7030.0000,4140.0000)");
        assertThat(h.prompts).containsExactly(new Surfacing.Prompt("GliderDOS", "A", 8));
    }

    @Test
    void firmware10NoValidFixSouthernHemisphereAndNan() throws IOException {
        Surfacing s = parse(dialog("fw10-device-error-no-fix.txt")).dialogs.get(0);
        assertThat(s.because()).isEqualTo("Device error");
        assertThat(s.gps()).isNull();
        assertThat(s.gpsProblem()).startsWith("no valid fix: GPS TooFar:").contains("GPS Invalid :  -3352.2911 N");
        assertThat(s.dr().lat()).isCloseTo(-(33 + 52.3080 / 60), within(1e-9));
        assertThat(s.dr().lon()).isCloseTo(151 + 17.4470 / 60, within(1e-9));
        assertThat(s.vehicleTime()).isEqualTo(Instant.parse("2026-11-26T04:07:55Z"));
        assertThat(s.value("m_leakdetect_voltage_aft")).isEqualTo(1.21);
        assertThat(s.sensors().get("m_water_vx").text()).isEqualTo("nan");
        assertThat(s.value("m_water_vx")).isNull();
        assertThat(s.sensors().get("x_hardware_ver").ageSeconds()).isEqualTo(1e308);
        assertThat(s.devices().errors().total()).isEqualTo(7);
        assertThat(s.countdown()).isEqualTo(50L);
    }

    @Test
    void aRelayedDialogWithoutTheGliderLineEndsWithTheCall() throws IOException {
        Heard h = new Heard();
        SurfaceDialogParser p = new SurfaceDialogParser(h);
        p.feed(dialog("relayed-no-glider-line.txt"));
        assertThat(h.dialogs).isEmpty();
        assertThat(p.inDialog()).isTrue();
        p.end();
        Surfacing s = h.dialogs.get(0);
        assertThat(s.vehicle()).isEqualTo("osu685");
        assertThat(s.gps().lat()).isCloseTo(33.16702, within(1e-4));
        assertThat(s.gps().lon()).isCloseTo(-117.69667, within(1e-4));
        assertThat(s.sensors()).hasSize(6);
        assertThat(s.aborts().total()).isEqualTo(9L);
        assertThat(s.end()).isEqualTo(Surfacing.End.CALL_ENDED);
    }

    @Test
    void anyChunkingGivesTheSameRecords() throws IOException {
        String all = dialog("fw7-surface-interval.txt") + dialog("fw8-abort-overdepth.txt")
                + dialog("fw10-device-error-no-fix.txt") + dialog("relayed-no-glider-line.txt");
        List<Surfacing> whole = parse(all).dialogs;
        assertThat(whole).hasSize(4);
        Random r = new Random(35);
        for (int round = 0; round < 20; round++) {
            Heard h = new Heard();
            SurfaceDialogParser p = new SurfaceDialogParser(h);
            for (int i = 0; i < all.length(); ) {
                int n = 1 + r.nextInt(round == 0 ? 1 : 40);
                p.feed(all.substring(i, Math.min(all.length(), i + n)));
                i += n;
            }
            p.end();
            assertThat(h.dialogs).isEqualTo(whole);
        }
        // LF only, as some relays send it, and lines as console entries carry them
        assertThat(parse(all.replace("\r\n", "\n")).dialogs).isEqualTo(whole);
        Heard lines = new Heard();
        SurfaceDialogParser p = new SurfaceDialogParser(lines);
        all.lines().forEach(p::line);
        p.end();
        assertThat(lines.dialogs).isEqualTo(whole);
    }

    @Test
    void theNextDialogEndsOneThatNeverEnded() {
        Heard h = parse("Glider a at surface.\nBecause:Surface interval [1]\nGlider a at surface.\nBecause:Hit a waypoint [2]\n");
        assertThat(h.dialogs).extracting(Surfacing::because).containsExactly("Surface interval", "Hit a waypoint");
        assertThat(h.dialogs.get(0).end()).isEqualTo(Surfacing.End.NEXT_DIALOG);
    }

    @Test
    void aFixAt91NorthIsKeptAsTextNotAFix() {
        Surfacing s = parse("Glider x at surface.\nGPS Location:  9100.000 N -7032.188 E measured 3.0 secs ago\n"
                + "DR  Location:  4137.99 N 18100.00 E measured 3.0 secs ago\n").dialogs.get(0);
        assertThat(s.gps()).isNull();
        assertThat(s.gpsProblem()).contains("9100.000 N");
        assertThat(s.dr()).isNull();
        assertThat(s.unknown()).singleElement().asString().contains("18100.00 E");
    }

    @Test
    void absurdNumbersAndControlBytesAreTextNotErrors() {
        Surfacing s = parse("Glider x\u0000 at surface.\r\nBecause:\u001b[31mAbort\u001b[0m\r\n"
                + "   sensor:m_battery(volts)=99999999999999999999999.5 1e+9999 secs ago\r\n"
                + "   sensor:m_vacuum(inHg)=-- 12 secs ago\r\n"
                + "devices:(t/m/s) errs: 999999999999999/ 0/ 0 warn: 0/0/0 oddity: 0/0/0\r\n"
                + "Curr Time: Xyz Foo 99 99:99:99 2026 MT: 5\r\n"
                + "ABORT HISTORY: total since reset: 99999999999999999999\r\n").dialogs.get(0);
        assertThat(s.vehicle()).isEqualTo("x");
        assertThat(s.becauseText()).isEqualTo("[31mAbort[0m");
        assertThat(s.value("m_battery")).isNull(); // more digits than any sensor has: kept as text
        assertThat(s.sensors().get("m_battery").text()).isEqualTo("99999999999999999999999.5");
        assertThat(s.sensors().get("m_battery").ageSeconds()).isInfinite();
        assertThat(s.sensors().get("m_vacuum").value()).isNull();
        assertThat(s.devices().errors().total()).isEqualTo(999999999999999L);
        assertThat(s.vehicleTime()).isNull();
        assertThat(s.unknown()).anyMatch(l -> l.startsWith("Curr Time: Xyz"))
                .anyMatch(l -> l.startsWith("ABORT HISTORY: total since reset: 9999"));
    }

    @Test
    void aMegabyteLineCostsOneLinesWorth() {
        StringBuilder b = new StringBuilder("Glider x at surface.\nBecause:");
        b.append("A".repeat(1 << 20)).append("\n   sensor:m_battery(volts)=15.1 2 secs ago\n");
        Surfacing s = parse(b.toString()).dialogs.get(0);
        assertThat(s.becauseText()).hasSize(SurfaceDialogParser.MAX_LINE - "Because:".length());
        assertThat(s.linesCut()).isEqualTo(1);
        assertThat(s.value("m_battery")).isEqualTo(15.1);
    }

    @Test
    void tenThousandSensorLinesAreBounded() {
        StringBuilder b = new StringBuilder("Glider x at surface.\n");
        for (int i = 0; i < 10_000; i++) {
            b.append("   sensor:m_s").append(i).append("(nodim)=").append(i).append(" 1.0 secs ago\n");
        }
        b.append("   sensor:m_s5(nodim)=-5 1.0 secs ago\n");
        long t0 = System.nanoTime();
        Surfacing s = parse(b.toString()).dialogs.get(0);
        assertThat(System.nanoTime() - t0).isLessThan(5_000_000_000L);
        assertThat(s.sensors()).hasSize(SurfaceDialogParser.MAX_SENSORS);
        assertThat(s.dropped()).isEqualTo(10_000 - SurfaceDialogParser.MAX_SENSORS);
        assertThat(s.value("m_s5")).isEqualTo(-5.0); // a known name is still updated
    }

    @Test
    void aDialogThatNeverEndsIsEndedAndThenIgnored() {
        Heard h = new Heard();
        SurfaceDialogParser p = new SurfaceDialogParser(h);
        p.feed("Glider x at surface.\n");
        for (int i = 0; i < 100_000; i++) {
            p.feed("junk line " + i + "\n");
        }
        assertThat(h.dialogs).hasSize(1);
        Surfacing s = h.dialogs.get(0);
        assertThat(s.end()).isEqualTo(Surfacing.End.TOO_LONG);
        assertThat(s.unknown()).hasSize(SurfaceDialogParser.MAX_UNKNOWN);
        assertThat(p.inDialog()).isFalse();
    }

    @Test
    void outsideADialogOnlyTheCountdownAndPromptsCount() {
        Heard h = parse("put c_x 1\n   sensor:c_x=1\nGliderDOS I -3 >\nHit Control-C within 30 seconds to abort the mission...\n"
                + "ABORT HISTORY: total since reset: 4\nC:\\>dir\n");
        assertThat(h.dialogs).isEmpty();
        assertThat(h.countdowns).containsExactly(30L);
        assertThat(h.prompts).containsExactly(new Surfacing.Prompt("GliderDOS", "I", -3), new Surfacing.Prompt("PicoDOS", null, null));
    }

    @Test
    void degreesAndMinutes() {
        assertThat(DegreesMinutes.degrees(4137.994, 'N')).isCloseTo(41.63323, within(1e-5));
        assertThat(DegreesMinutes.degrees(-7032.188, 'E')).isCloseTo(-70.53647, within(1e-5));
        assertThat(DegreesMinutes.degrees(7032.188, 'W')).isCloseTo(-70.53647, within(1e-5));
        assertThat(DegreesMinutes.degrees(4160.0, 'N')).isNaN();
        assertThat(DegreesMinutes.degrees(69696969, 'N')).isNaN();
    }
}
