package org.ripv.services.serial;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.InputStream;
import java.io.OutputStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.VehicleEvent;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Vehicles that call in, over real sockets: a {@code listen://} link named {@code ru29}, callers
 * that print unsolicited lines, GPS fixes, junk and floods, a second caller, and the glider
 * simulator calling in and diving. What the service publishes is collected by the probe's sink.
 */
class VehicleCallTest {
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    Path tmp;

    SerialPortServer serial;
    ServiceProbe probe;
    GliderSimulator glider;

    private void start(CallSettings call) throws Exception {
        start(new VehicleLink(SimulatorOverTcpTest.settings("listen://127.0.0.1:0"), call));
    }

    private void start(VehicleLink link) throws Exception {
        serial = SerialPortServer.withCalls("testhost", List.of(link), null, false, tmp.resolve("work"));
        probe = new ServiceProbe(serial);
        serial.start();
    }

    @AfterEach
    void stop() {
        if (glider != null) {
            glider.close();
        }
        if (serial != null) {
            serial.stop();
        }
    }

    private Socket call() throws Exception {
        Socket s = new Socket("127.0.0.1", serial.listenPort("ru29"));
        s.setSoTimeout(10_000);
        return s;
    }

    private static void say(Socket s, String text) throws Exception {
        s.getOutputStream().write(text.getBytes(StandardCharsets.ISO_8859_1));
        s.getOutputStream().flush();
    }

    private void awaitEvent(VehicleEvent event, int count) {
        Eventually.await(count + " x " + event + " in " + probe.console, T,
                () -> probe.events("ru29").stream().filter(e -> e.event() == event).count() >= count);
    }

    private ConsoleEntry event(VehicleEvent event, int nth) {
        return probe.events("ru29").stream().filter(e -> e.event() == event).skip(nth - 1).findFirst().orElseThrow();
    }

    @Test
    void aCallerSurfacesWithItsPositionItsLinesStreamInOrderAndHangingUpIsADive() throws Exception {
        start(CallSettings.defaults().withName("ru29"));
        assertThat(serial.handles()).containsExactly("ru29");
        assertThat(probe.status("ru29").available()).isFalse();
        assertThat(probe.status("ru29").detail()).contains("no call yet").contains("waiting for calls on listen://127.0.0.1:");
        assertThat(probe.send("ru29", "dir", T).last().footer().errorCode()).isEqualTo(ErrorCode.NOT_AVAILABLE);

        try (Socket s = call()) {
            say(s, "\r\nGlider ru29 at surface.\r\nBecause:Surface interval [1]\r\nVehicle Name: ru29\r\n");
            say(s, "GPS Location:  4137.994 N -7032.188 E measured     26.0 secs ago\r\n");
            for (int i = 1; i <= 20; i++) {
                say(s, "   sensor:line_" + i + "=" + i + "\r\n");
            }
            say(s, "Hit Control-C within 10 seconds to abort the mission...\r\n"); // the dialog is over
            awaitEvent(VehicleEvent.SURFACED, 1);
            ConsoleEntry surfaced = event(VehicleEvent.SURFACED, 1);
            assertThat(surfaced.lat()).isCloseTo(41 + 37.994 / 60, org.assertj.core.data.Offset.offset(1e-9));
            assertThat(surfaced.lon()).isCloseTo(-70.5364667, org.assertj.core.data.Offset.offset(1e-6));
            assertThat(surfaced.text()).contains("call 1").contains("caller 127.0.0.1:");
            Eventually.await("all lines", T, () -> probe.lines("ru29").contains("   sensor:line_20=20"));
            List<String> lines = probe.lines("ru29");
            assertThat(lines.subList(0, 4)).containsExactly("Glider ru29 at surface.", "Because:Surface interval [1]",
                    "Vehicle Name: ru29", "GPS Location:  4137.994 N -7032.188 E measured     26.0 secs ago");
            for (int i = 1; i <= 20; i++) {
                assertThat(lines.get(3 + i)).isEqualTo("   sensor:line_" + i + "=" + i);
            }
            assertThat(probe.console).allSatisfy(e -> assertThat(e.mailbox()).isEqualTo("<SerialPortServer>::<testhost>ru29"));
            assertThat(probe.status("ru29").available()).isTrue();
            assertThat(probe.status("ru29").detail()).contains("on call since").doesNotContain("call 1"); // the server counts
        }
        awaitEvent(VehicleEvent.DIVED, 1);
        ConsoleEntry dived = event(VehicleEvent.DIVED, 1);
        assertThat(dived.text()).contains("hung up");
        assertThat(dived.lat()).isNotNull();
        Eventually.await("dived in status", T, () -> probe.status("ru29").detail().contains("dived at"));
        assertThat(probe.status("ru29").available()).isFalse();
        assertThat(probe.events("ru29")).extracting(ConsoleEntry::event)
                .containsExactly(VehicleEvent.SURFACED, VehicleEvent.DIVED);

        // the next call is taken just the same; this caller hangs up in the middle of its dialog: a dropped call
        try (Socket s = call()) {
            say(s, "GPS Location:  4138.994 N -7031.188 E measured 1.0 secs ago\r\n   sensor:m_battery(volts)=15.1\r\n");
            awaitEvent(VehicleEvent.SURFACED, 2);
            assertThat(event(VehicleEvent.SURFACED, 2).text()).contains("call 2");
        }
        awaitEvent(VehicleEvent.LINK_LOST, 1);
        assertThat(event(VehicleEvent.LINK_LOST, 1).text()).startsWith("the caller hung up in the middle of its surface dialog");
        assertThat(probe.events("ru29")).extracting(ConsoleEntry::event)
                .containsExactly(VehicleEvent.SURFACED, VehicleEvent.DIVED, VehicleEvent.SURFACED, VehicleEvent.LINK_LOST);
        Eventually.await("lost in status", T, () -> probe.status("ru29").detail().contains("lost at"));
    }

    @Test
    void aSecondCallerGetsOneLineAndIsHungUpOnWhileTheFirstCallGoesOn() throws Exception {
        start(CallSettings.defaults().withName("ru29"));
        try (Socket first = call()) {
            say(first, "first caller here\r\n");
            Eventually.await("first line", T, () -> probe.lines("ru29").contains("first caller here"));
            try (Socket second = call()) {
                say(second, "second caller mixing in\r\n");
                InputStream in = second.getInputStream();
                byte[] all = in.readAllBytes(); // ends when the service hangs up
                assertThat(new String(all, StandardCharsets.US_ASCII)).isEqualTo(
                        "RIPV: ru29 is on a call already; try again later\r\n");
            }
            say(first, "still the first\r\n");
            Eventually.await("first goes on", T, () -> probe.lines("ru29").contains("still the first"));
            assertThat(probe.lines("ru29")).doesNotContain("second caller mixing in");
            assertThat(probe.events("ru29")).extracting(ConsoleEntry::event)
                    .doesNotContain(VehicleEvent.DIVED, VehicleEvent.LINK_LOST);
            assertThat(probe.status("ru29").available()).isTrue();
        }
        awaitEvent(VehicleEvent.DIVED, 1);
        assertThat(probe.events("ru29")).extracting(ConsoleEntry::event)
                .containsExactly(VehicleEvent.SURFACED, VehicleEvent.DIVED);
    }

    @Test
    void aCallerFromAnAddressNotInCallersGetsOneLineAndIsNeverTheVehicle() throws Exception {
        // The link takes calls only from 127.0.0.2 (standing for the RUDICS gateway); 127.0.0.1 is someone else.
        start(CallSettings.defaults().withName("ru29").withCallers(org.ripv.security.AddressRanges.parse("127.0.0.2/32")));
        int port = serial.listenPort("ru29");
        try (Socket stranger = new Socket("127.0.0.1", port, java.net.InetAddress.getByName("127.0.0.1"), 0)) {
            stranger.setSoTimeout(10_000);
            say(stranger, "Glider ru29 at surface.\r\nGPS Location:  4137.994 N -7032.188 E measured 1.0 secs ago\r\n");
            assertThat(new String(stranger.getInputStream().readAllBytes(), StandardCharsets.US_ASCII))
                    .isEqualTo("RIPV: calls from this address are not taken on this link\r\n");
        }
        try (Socket gateway = new Socket("127.0.0.1", port, java.net.InetAddress.getByName("127.0.0.2"), 0)) {
            gateway.setSoTimeout(10_000);
            say(gateway, "Glider ru29 at surface.\r\n");
            awaitEvent(VehicleEvent.SURFACED, 1);
            assertThat(event(VehicleEvent.SURFACED, 1).text()).contains("caller 127.0.0.2:");
        }
        awaitEvent(VehicleEvent.LINK_LOST, 1); // it hung up right after "at surface.": the call dropped
        assertThat(probe.lines("ru29")).containsExactly("Glider ru29 at surface.");
        assertThat(probe.events("ru29")).hasSize(2);
    }

    @Test
    void aCallerThatSaysNothingForTheQuietTimeIsHungUpSoTheVehicleCanCall() throws Exception {
        start(CallSettings.defaults().withName("ru29").withQuiet(Duration.ofSeconds(1)));
        try (Socket squatter = call()) {
            say(squatter, "hello\r\n");
            assertThat(squatter.getInputStream().readAllBytes()).isEmpty(); // returns when we are hung up on
        }
        awaitEvent(VehicleEvent.DIVED, 1);
        assertThat(event(VehicleEvent.DIVED, 1).text()).isEqualTo("quiet for 1 s: hung up");
        try (Socket vehicle = call()) {
            say(vehicle, "GPS Location:  4137.994 N -7032.188 E measured 26.0 secs ago\r\n");
            awaitEvent(VehicleEvent.SURFACED, 2);
        }
    }

    @Test
    void binaryJunkAndAMegabyteWithoutALineEndAreCutPrintableAndBounded() throws Exception {
        start(CallSettings.defaults().withName("ru29").withLimits(100, 1000));
        try (Socket s = call()) {
            byte[] junk = new byte[64 * 1024];
            new Random(9).nextBytes(junk);
            s.getOutputStream().write(junk);
            say(s, "\r\nmarker one\r\n");
            byte[] mega = new byte[1024 * 1024];
            Arrays.fill(mega, (byte) 'x');
            s.getOutputStream().write(mega);
            say(s, "\r\nmarker two\r\n");
            Eventually.await("marker two", T, () -> probe.lines("ru29").contains("marker two"));
        }
        List<String> lines = probe.lines("ru29");
        assertThat(lines).contains("marker one");
        for (String l : lines) {
            assertThat(l.length()).isLessThanOrEqualTo(100 + " [line cut at 100 characters]".length());
            assertThat(l.chars().noneMatch(c -> c < 0x20 || c == 0x7F)).as(l).isTrue();
        }
        assertThat(lines).contains("x".repeat(100) + " [line cut at 100 characters]");
        assertThat(lines).contains("[" + (1024 * 1024 - 100) + " more characters of that line dropped]");
        assertThat(lines.stream().anyMatch(l -> l.indexOf(LineAssembler.REPLACEMENT) >= 0)).isTrue();
        awaitEvent(VehicleEvent.DIVED, 1);
    }

    @Test
    void tenThousandLinesASecondAreBoundedAndTheSkippedOnesCounted() throws Exception {
        start(CallSettings.defaults().withName("ru29").withLimits(1024, 200));
        long started;
        try (Socket s = call()) {
            StringBuilder flood = new StringBuilder();
            for (int i = 0; i < 10_000; i++) {
                flood.append("flood line ").append(i).append("\r\n");
            }
            started = System.nanoTime();
            say(s, flood.toString());
            say(s, "the end\r\n");
            Eventually.await("the end or its skip", T, () -> probe.lines("ru29").stream()
                    .mapToLong(VehicleCallTest::count).sum() >= 10_001);
        }
        double seconds = (System.nanoTime() - started) / 1e9;
        List<String> lines = probe.lines("ru29");
        long shown = lines.stream().filter(l -> !l.startsWith("[")).count();
        long skipped = lines.stream().filter(l -> l.startsWith("[")).mapToLong(VehicleCallTest::count).sum();
        assertThat(shown + skipped).isEqualTo(10_001);
        assertThat(skipped).isPositive();
        assertThat(lines.stream().filter(l -> l.startsWith("[")).count()).as("markers at most once a second")
                .isLessThanOrEqualTo((long) seconds + 2);
        assertThat((double) shown).isLessThanOrEqualTo(200 + 200 * (seconds + 1));
        assertThat(lines.stream().filter(l -> l.startsWith("[")).findFirst().orElseThrow())
                .matches("\\[\\d+ lines skipped: the vehicle printed \\d+ lines/s, more than the link's 200]");
        // in order: the lines shown are an increasing subsequence
        int last = -1;
        for (String l : lines) {
            if (l.startsWith("flood line ")) {
                int n = Integer.parseInt(l.substring("flood line ".length()));
                assertThat(n).isGreaterThan(last);
                last = n;
            }
        }
    }

    /** 1 for a line, N for an "[N lines skipped" marker. */
    private static long count(String line) {
        Matcher m = Pattern.compile("^\\[(\\d+) lines skipped").matcher(line);
        return m.find() ? Long.parseLong(m.group(1)) : 1;
    }

    @Test
    void alertLinesRaiseAnAlertWithTheLine() throws Exception {
        start(CallSettings.defaults().withName("ru29"));
        try (Socket s = call()) {
            say(s, "GPS Location:  4137.994 N -7032.188 E measured 26.0 secs ago\r\n");
            say(s, "all well\r\nLEAK detected in forward hull\r\n");
            awaitEvent(VehicleEvent.ALERT, 1);
        }
        ConsoleEntry alert = event(VehicleEvent.ALERT, 1);
        assertThat(alert.text()).isEqualTo("LEAK detected in forward hull");
        assertThat(alert.lat()).isNotNull();
        assertThat(probe.events("ru29")).extracting(ConsoleEntry::event).doesNotHaveDuplicates();
    }

    @Test
    void theSimulatorCallsInAnswersCommandsAndDivesAndCallsAgain() throws Exception {
        start(CallSettings.defaults().withName("ru29"));
        glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(1), SimulatorOverTcpTest.YMODEM);
        glider.call("127.0.0.1", serial.listenPort("ru29"), "ru29", Duration.ofSeconds(1), Duration.ofSeconds(6));
        awaitEvent(VehicleEvent.SURFACED, 1);
        ConsoleEntry first = event(VehicleEvent.SURFACED, 1);
        assertThat(first.lat()).isCloseTo(41 + 37.994 / 60, org.assertj.core.data.Offset.offset(1e-6));
        assertThat(first.lon()).isCloseTo(-(70 + 32.188 / 60), org.assertj.core.data.Offset.offset(1e-6));
        assertThat(probe.lines("ru29")).contains("Glider ru29 at surface.", "Vehicle Name: ru29");

        ServiceProbe.Answer dir = probe.send("ru29", "dir", T);
        assertThat(dir.ok()).as(dir.text()).isTrue();
        assertThat(dir.text()).contains("MISSION1.LOG");
        Eventually.await("dir in the console", T, () -> probe.lines("ru29").stream().anyMatch(l -> l.startsWith("MISSION1.LOG")));
        List<ConsoleEntry> commands = probe.console("ru29", ConsoleEntry.Kind.COMMAND);
        assertThat(commands).extracting(ConsoleEntry::user, ConsoleEntry::text)
                .containsExactly(org.assertj.core.groups.Tuple.tuple("alice", "dir"));
        int commandAt = probe.console.indexOf(commands.get(0));
        int listingAt = probe.console.indexOf(probe.console.stream()
                .filter(e -> e.text().startsWith("MISSION1.LOG")).findFirst().orElseThrow());
        assertThat(commandAt).isLessThan(listingAt);
        assertThat(probe.lines("ru29")).doesNotContain("dir", "C:\\>dir", "C:\\>");

        ServiceProbe.Answer got = probe.send("ru29", "ymodem:get SENSOR.DAT", T);
        assertThat(got.ok()).as(got.text()).isTrue();
        Eventually.await("transfer done", T, () -> probe.events("ru29").stream()
                .anyMatch(e -> e.event() == VehicleEvent.TRANSFER_DONE));
        assertThat(probe.console("ru29", ConsoleEntry.Kind.TRANSFER)).extracting(ConsoleEntry::text)
                .contains("receiving SENSOR.DAT (4096 bytes)", "received SENSOR.DAT (4096 bytes)");
        assertThat(probe.console("ru29", ConsoleEntry.Kind.TRANSFER)).allSatisfy(e -> assertThat(e.user()).isEqualTo("alice"));
        for (String l : probe.lines("ru29")) {
            assertThat(l.indexOf(LineAssembler.REPLACEMENT)).as("no binary in the console: " + l).isNegative();
        }
        ServiceProbe.Answer missing = probe.send("ru29", "ymodem:get NOSUCH.LOG", T);
        assertThat(missing.ok()).isFalse();
        Eventually.await("transfer failed", T, () -> probe.events("ru29").stream()
                .anyMatch(e -> e.event() == VehicleEvent.TRANSFER_FAILED));
        assertThat(probe.events("ru29").stream().filter(e -> e.event() == VehicleEvent.TRANSFER_FAILED).findFirst()
                .orElseThrow().text()).contains("'ymodem:get NOSUCH.LOG' for alice").contains("File not found - NOSUCH.LOG");

        awaitEvent(VehicleEvent.DIVED, 1);
        awaitEvent(VehicleEvent.SURFACED, 2);
        ConsoleEntry second = event(VehicleEvent.SURFACED, 2);
        assertThat(second.lat()).isGreaterThan(first.lat());
        assertThat(second.text()).contains("call 2");
        if (System.getenv("DUMP_CONSOLE") != null) {
            probe.console.forEach(e -> System.err.println("CONSOLE " + e.kind() + " " + e.user() + " " + e.event() + " | " + e.text()));
        }
    }

    @Test
    void aServiceRestartedInTheMiddleOfACallTakesTheNextCall() throws Exception {
        start(CallSettings.defaults().withName("ru29"));
        int port = serial.listenPort("ru29");
        glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(1), SimulatorOverTcpTest.YMODEM);
        glider.call("127.0.0.1", port, "ru29", Duration.ofSeconds(1), Duration.ofSeconds(30));
        awaitEvent(VehicleEvent.SURFACED, 1);
        serial.stop(); // mid-call: the glider is hung up on
        start(new VehicleLink(SimulatorOverTcpTest.settings("listen://127.0.0.1:" + port),
                CallSettings.defaults().withName("ru29")));
        assertThat(probe.status("ru29").detail()).contains("no call yet");
        awaitEvent(VehicleEvent.SURFACED, 1); // the glider's next call, at the new service
        assertThat(event(VehicleEvent.SURFACED, 1).text()).contains("call 1");
        assertThat(probe.send("ru29", "dir", T).text()).contains("MISSION1.LOG");
    }

    @Test
    void aLinkWithoutCarrierOrCallerSurfacesOnTheDialogAndDivesWhenQuietAndALostLinkIsLost() throws Exception {
        try (ServerSocket vehicle = new ServerSocket(0)) {
            VehicleLink link = new VehicleLink(SimulatorOverTcpTest.settings("tcp://127.0.0.1:" + vehicle.getLocalPort()),
                    CallSettings.defaults().withName("ru29").withQuiet(Duration.ofSeconds(1)));
            start(link);
            try (Socket s = vehicle.accept()) {
                say(s, "some chatter before the dialog\r\n");
                Eventually.await("chatter", T, () -> probe.lines("ru29").contains("some chatter before the dialog"));
                assertThat(probe.events("ru29")).isEmpty();
                say(s, "Glider ru29 at surface.\r\nGPS Location:  4137.994 S 7032.188 W measured 2.0 secs ago\r\n");
                awaitEvent(VehicleEvent.SURFACED, 1);
                assertThat(event(VehicleEvent.SURFACED, 1).lat()).isCloseTo(-41.6332, org.assertj.core.data.Offset.offset(1e-4));
                assertThat(event(VehicleEvent.SURFACED, 1).lon()).isCloseTo(-70.5365, org.assertj.core.data.Offset.offset(1e-4));
                awaitEvent(VehicleEvent.DIVED, 1);
                assertThat(event(VehicleEvent.DIVED, 1).text()).contains("quiet for 1 s");
                OutputStream out = s.getOutputStream();
                out.flush();
            }
            awaitEvent(VehicleEvent.LINK_LOST, 1);
            Eventually.await("lost in status", T, () -> probe.status("ru29").detail().contains("lost at"));
        }
    }
}
