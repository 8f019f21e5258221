package org.ripv.it.console;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.it.TestSystem;
import org.ripv.messages.Priority;
import org.ripv.probe.FreePorts;
import org.ripv.server.ServerConfig;
import org.ripv.service.ServiceConnector;

/**
 * What a vehicle says while the server is away — restarting, or a standby taking over — reaches
 * the transcript once a server is back: the service keeps the entries the server did not take
 * and offers them again, and the server answers only once they are stored.
 */
class ServerAwayTest {
    @TempDir
    Path dir;

    private ServerConfig config;
    private VehicleConsoleService vehicle;
    private ServiceConnector connector;
    private TestSystem sys;

    /** A server on fixed free ports, and a vehicle's service that outlives it and finds it again. */
    @BeforeEach
    void start() throws Exception {
        int[] ports = FreePorts.several(2);
        config = ServerConfig.forTests(dir.resolve("server")).withPorts(ports[0], ports[1], -1);
        vehicle = new VehicleConsoleService("localhost", "ru29");
        sys = TestSystem.start(config);
        sys.user("alice", "operators");
        connector = ServiceConnector.connect(vehicle, sys.serviceOptions());
        assertThat(connector.awaitRegistered(Duration.ofSeconds(20))).isTrue();
    }

    @AfterEach
    void stop() {
        if (connector != null) {
            connector.close();
        }
        vehicle.stop();
        if (sys != null) {
            sys.close();
        }
    }

    @Test
    void aWorkflowRunningWhenTheServerStoppedResumesWhenItIsBackWhileTheCallGoesOn() throws Exception {
        String box = vehicle.mailbox();
        var alice = sys.login("alice");
        Path wf = dir.resolve("wait.wf");
        java.nio.file.Files.writeString(wf, "send say first\nwait-for 'go on' timeout=5m\nsend say last\n");
        alice.upload(wf, "wait.wf", null);
        ConsoleSessionTest.call(alice, "?queue add " + box + " wait.wf");
        vehicle.event(org.ripv.messages.VehicleEvent.SURFACED, "", 41.5, -70.5);
        ConsoleSessionTest.awaitQueue(alice, box, "running step 2/3", Duration.ofSeconds(20));
        sys.close();

        // The server comes back (or a standby takes over) while the vehicle is still on the
        // call: the workflow carries on at its cut step now, not on the vehicle's next call.
        sys = TestSystem.start(config);
        var back = sys.login("alice");
        ConsoleSessionTest.awaitQueue(back, box, "running step 2/3", Duration.ofSeconds(30));
        vehicle.line("go on");
        long end = System.nanoTime() + Duration.ofSeconds(20).toNanos();
        String receipts = "";
        while (System.nanoTime() < end && !receipts.contains("result: DONE")) {
            receipts = ConsoleSessionTest.call(back, "?receipts " + box).footer().replyText();
            Thread.sleep(100);
        }
        assertThat(receipts).contains("(resumed at step 2)").contains("result: DONE");
    }

    @Test
    void linesSaidWhileTheServerIsAwayAreInItsTranscriptWhenItIsBack() throws Exception {
        vehicle.event(org.ripv.messages.VehicleEvent.SURFACED, "", 41.5, -70.5);
        vehicle.line("before the server went away");
        sys.close();

        for (int i = 1; i <= 50; i++) {
            vehicle.line("said while away " + i);
        }
        Thread.sleep(500);
        sys = TestSystem.start(config);
        long end = System.nanoTime() + Duration.ofSeconds(30).toNanos();
        String history = "";
        while (System.nanoTime() < end && !history.contains("said while away 50")) {
            Thread.sleep(200);
            history = sys.login("alice").call("", "?history " + vehicle.mailbox() + " --last 100", Priority.NORMAL,
                    Duration.ofSeconds(10), null).footer().replyText();
        }
        assertThat(history).contains("before the server went away");
        int at = -1;
        for (int i = 1; i <= 50; i++) {
            int next = history.indexOf("said while away " + i + "\n") >= 0 ? history.indexOf("said while away " + i + "\n")
                    : history.indexOf("said while away " + i);
            assertThat(next).as("line %d, in order", i).isGreaterThan(at);
            at = next;
        }
        // The service kept running through it, so its call did too: still on call, not lost.
        Thread.sleep(1000);
        assertThat(sys.server().console().state(vehicle.mailbox()).state())
                .isEqualTo(org.ripv.messages.SessionState.State.ON_CALL);
    }
}
