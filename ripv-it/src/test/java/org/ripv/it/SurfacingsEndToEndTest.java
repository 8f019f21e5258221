package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.fasterxml.jackson.core.type.TypeReference;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.console.Pushes;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.messages.VehicleEvent;
import org.ripv.probe.FreePorts;

/**
 * Issue 35 as launched: the SerialPortServer from its jar with a {@code listen://} link, the
 * glider simulator from its jar calling it with real-format GliderDOS dialogs (an abort on its
 * second call, a leak from then on). The server keeps a call record per surfacing
 * ({@code ?surfacings}, text and JSON), raises ALERTs naming their cause and none for the
 * countdown text or sensor names, OVERDUE when the glider is late (a 3 s interval) and again when
 * it calls; a call dropped in the middle of the dialog is LINK_LOST, not DIVED.
 */
class SurfacingsEndToEndTest {
    static final Path ROOT = LaunchedJars.ROOT;
    static final Duration T = Duration.ofSeconds(90);

    @TempDir
    Path dir;
    TestSystem sys;
    LaunchedJars jars;

    @AfterEach
    void stop() throws Exception {
        if (jars != null) {
            jars.close();
        }
        if (sys != null) {
            sys.close();
        }
    }

    /** The server, and the SerialPortServer launched with a listen:// link named ru29; returns its port. */
    private int start(String linkOptions) throws Exception {
        for (String m : List.of("ripv-server", "ripv-services")) {
            assumeTrue(Files.isRegularFile(ROOT.resolve(m + "/target/" + m + ".jar")), "needs the jars (mvn package builds them)");
        }
        Files.createDirectories(dir.resolve("home/.ripv"));
        jars = new LaunchedJars(dir);
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators").user("olga", "observers");
        int port = FreePorts.one();
        Path secret = dir.resolve("service.secret");
        Files.writeString(secret, sys.secret());
        Path serviceLog = dir.resolve("serial.log");
        jars.launch(serviceLog, "service", "serial", "--server", "localhost:" + sys.server().registryPort(), "--secret-file",
                secret.toString(), "--no-enumerate", "--work", dir.resolve("work").toString(), "--link",
                "listen://127.0.0.1:" + port + ",name=ru29,idle-timeout=1000" + linkOptions + ",prompt-regex=Glider[Dd][Oo][Ss] [A-Z] -?[0-9]+ >|C:\\\\>");
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (sys.server().serviceCount() == 0) {
            assertThat(System.nanoTime() < end).as("the SerialPortServer registered; its log: " + Files.readString(serviceLog)).isTrue();
            Thread.sleep(100);
        }
        return port;
    }

    private static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }

    @Test
    void callRecordsAlertsWithTheirCauseAndAnOverdueGlider() throws Exception {
        // ru29 is expected every 3 s (its link's overdue=, +1 s grace from the rules file); it dives for
        // 9 s between calls, so it is late each dive
        int port = start(",overdue=3s");
        Files.writeString(sys.dataDir().resolve("surfacing-alerts.conf"), "# test rules\nru29 overdue 1h\n* overdue.grace 1s\n");
        ClientSocketHandler alice = sys.login("alice");
        String mailbox = "<SerialPortServer>::<localhost>ru29";
        Pushes pushes = Pushes.on(alice);
        assertThat(call(alice, "?watch " + mailbox).status()).isEqualTo(Status.OK);

        jars.add(SimulatorProcess.start(dir.resolve("simulator.log"), List.of("--call", "127.0.0.1:" + port, "--name", "ru29",
                "--dialog", "gliderdos", "--surface-seconds", "2", "--dive-seconds", "9", "--dir",
                Files.createDirectories(dir.resolve("glider")).toString(), "--abort-on-call", "2", "--leak-from-call", "2")));

        assertThat(pushes.await(e -> e.event() == VehicleEvent.ALERT && e.text().startsWith("new abort"), T))
                .as(String.join("\n", pushes.texts())).isTrue();
        assertThat(pushes.await(e -> e.event() == VehicleEvent.ALERT && e.text().startsWith("leak:"), T)).isTrue();
        assertThat(pushes.await(e -> e.event() == VehicleEvent.ALERT && e.text().startsWith("surfaced because"), T)).isTrue();
        assertThat(pushes.await(e -> e.event() == VehicleEvent.OVERDUE && e.text().startsWith("called again"), T))
                .as(String.join("\n", pushes.texts())).isTrue();
        List<ConsoleEntry> alerts = pushes.entries.stream().filter(e -> e.event() == VehicleEvent.ALERT).toList();
        assertThat(alerts).extracting(ConsoleEntry::text).contains(
                "new abort: MS_ABORT_OVERDEPTH: dive_to: depth 1012.3 > max depth 1000.0 at "
                        + alerts.get(0).text().replaceAll(".* at (\\S+) \\(1 since reset\\)$", "$1") + " (1 since reset)",
                "leak: m_leakdetect_voltage_aft 1.21 V, below 2.00 V", "surfaced because: Abort [MS_ABORT_OVERDEPTH]");
        // the countdown, "abort it", ABORT HISTORY and sensor names are never alerts
        assertThat(alerts).extracting(ConsoleEntry::text).noneMatch(t -> t.contains("Hit Control") || t.contains("ABORT HISTORY")
                || t.contains("sensor:"));
        assertThat(alerts).allSatisfy(a -> assertThat(a.lat()).isNotNull());
        ConsoleEntry late = pushes.entries.stream().filter(e -> e.event() == VehicleEvent.OVERDUE).findFirst().orElseThrow();
        assertThat(late.text()).startsWith("no call for").contains("expected every 3 s (its link's overdue=) + 1 s grace");
        // a call that ends after its dialog is a dive, not a lost link
        assertThat(pushes.entries).extracting(ConsoleEntry::event).contains(VehicleEvent.DIVED).doesNotContain(VehicleEvent.LINK_LOST);

        OutgoingServerMessage table = call(alice, "?surfacings ru29");
        assertThat(table.status()).as(table.footer().replyText()).isEqualTo(Status.OK);
        assertThat(table.footer().replyText()).contains("call records of " + mailbox).contains("time_utc").contains("battery_v")
                .contains("MS_ABORT_OVERDEPTH").contains("m_coulomb_amphr_total");
        TableResult t = (TableResult) table.footer().result();
        assertThat(t.columns()).startsWith("time_utc", "vehicle", "because", "mission", "gps_lat", "gps_lon", "gps_age_s", "dr_lat",
                "dr_lon", "battery_v", "vacuum_inhg", "leak").contains("water_vx", "water_vy", "abort_total", "abort_cause",
                "abort_details", "new_abort", "c_wpt_lat", "m_leakdetect_voltage_aft", "m_depth");
        String json = call(alice, "?surfacings ru29 --last 2 --json").footer().replyText();
        List<Map<String, Object>> records = new ObjectMapper().readValue(json, new TypeReference<>() {});
        assertThat(records).hasSizeGreaterThanOrEqualTo(2);
        Map<String, Object> first = call(alice, "?surfacings ru29 --last 1000 --json").footer().replyText().isEmpty() ? null
                : new ObjectMapper().readValue(call(alice, "?surfacings ru29 --last 1000 --json").footer().replyText(),
                        new TypeReference<List<Map<String, Object>>>() {}).get(0);
        assertThat(first).containsEntry("because", "Surface interval [1]").containsEntry("new_abort", false)
                .containsEntry("leak", false).containsEntry("abort_total", 0).containsEntry("vehicle", "ru29");
        assertThat((Double) first.get("gps_lat")).isBetween(41.63, 41.64);
        Map<String, Object> second = new ObjectMapper().readValue(call(alice, "?surfacings ru29 --last 1000 --json").footer()
                .replyText(), new TypeReference<List<Map<String, Object>>>() {}).get(1);
        assertThat(second).containsEntry("new_abort", true).containsEntry("abort_cause", "MS_ABORT_OVERDEPTH")
                .containsEntry("leak", true).containsEntry("m_leakdetect_voltage_aft", 1.21).containsEntry("abort_total", 1);
        // bad requests are refused with what to do
        assertThat(call(alice, "?surfacings ru29 --last 0").footer().replyText()).contains("--last takes a whole number");
        assertThat(call(alice, "?surfacings nobody").status()).isEqualTo(Status.ERROR);
    }

    @Test
    void aCallDroppedInTheMiddleOfItsDialogIsLinkLostNotADive() throws Exception {
        int port = start("");
        ClientSocketHandler alice = sys.login("alice");
        String mailbox = "<SerialPortServer>::<localhost>ru29";
        Pushes pushes = Pushes.on(alice);
        assertThat(call(alice, "?watch " + mailbox).status()).isEqualTo(Status.OK);
        // the line drops after 400 bytes: inside the surface dialog
        jars.add(SimulatorProcess.start(dir.resolve("simulator.log"), List.of("--call", "127.0.0.1:" + port, "--name", "ru29",
                "--dialog", "gliderdos", "--surface-seconds", "5", "--dive-seconds", "5", "--drop-after", "400b", "--dir",
                Files.createDirectories(dir.resolve("glider")).toString())));
        assertThat(pushes.await(e -> e.event() == VehicleEvent.LINK_LOST, T)).as(String.join("\n", pushes.texts())).isTrue();
        ConsoleEntry lost = pushes.entries.stream().filter(e -> e.event() == VehicleEvent.LINK_LOST).findFirst().orElseThrow();
        assertThat(lost.text()).startsWith("the caller hung up in the middle of its surface dialog: the call dropped");
        assertThat(pushes.entries).extracting(ConsoleEntry::event).doesNotContain(VehicleEvent.DIVED);
        assertThat(call(alice, "?status " + mailbox).footer().replyText()).contains("lost");
    }
}
