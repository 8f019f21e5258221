package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.services.datavis.DataVisServer;
import org.ripv.services.datavis.WorkerMode;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 12's cancels end to end, through the server: a plain vehicle command (the link's
 * interrupt, then the prompt; the console's transcript says who cancelled) and a DataVis plot
 * (the wait ends and the worker is stopped).
 */
class VehicleCancelEndToEndTest {
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
        if (glider != null) {
            glider.close();
        }
    }

    private static String status(ClientSocketHandler c, String mb) throws Exception {
        return c.call("", "?status " + mb, Priority.NORMAL, T, null).footer().replyText();
    }

    private static void await(String what, java.util.concurrent.Callable<Boolean> done) throws Exception {
        long end = System.nanoTime() + T.toNanos();
        while (System.nanoTime() < end) {
            if (done.call()) {
                return;
            }
            Thread.sleep(100);
        }
        throw new AssertionError("gave up waiting for " + what);
    }

    @Test
    void anOperatorCancelsAPilotsRunningVehicleCommandAndTheTranscriptSaysWho() throws Exception {
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), SerialEndToEndTest.YMODEM);
        int port = glider.listen(0);
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators").user("bob", "operators");
        SerialPortServer serial = new SerialPortServer("localhost", List.of(LinkSettings.defaults("tcp://127.0.0.1:" + port)
                .withIdleTimeout(Duration.ofSeconds(1)).withYmodem(SerialEndToEndTest.YMODEM)), null, false, dir.resolve("work"));
        sys.register(serial);
        String mb = "<SerialPortServer>::<localhost>" + serial.handles().get(0);
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler bob = sys.login("bob");
        assertThat(bob.call("", "?watch " + mb, Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);

        long id = alice.nextId();
        CompletableFuture<OutgoingServerMessage> monitor = alice.send(Header.request(id, mb, "monitor 120", Priority.NORMAL), null);
        await("?status to show the command", () -> status(bob, mb).contains("busy: running 'monitor 120' for alice"));
        OutgoingServerMessage c = bob.call("", "?cancel " + id + " " + alice.session().clientId(), Priority.NORMAL, T, null);
        assertThat(c.status()).as(c.footer().replyText()).isEqualTo(Status.OK);
        OutgoingServerMessage r = monitor.get(20, TimeUnit.SECONDS);
        assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.CANCELLED);
        assertThat(r.footer().replyText()).startsWith("cancelled by bob: interrupted 'monitor 120' with ^C; "
                + "the vehicle is back at its prompt");

        OutgoingServerMessage next = alice.call(mb, "dir", Priority.NORMAL, T, null);
        assertThat(next.status()).isEqualTo(Status.OK);
        assertThat(next.footer().replyText()).contains("MISSION1.LOG").doesNotContain("m_depth");
        assertThat(status(alice, mb)).contains(": available");
        await("the transcript to name the canceller", () -> alice.call("", "?history " + mb, Priority.NORMAL, T, null)
                .footer().replyText().contains("?cancel #" + id + " 'monitor 120' of alice (while it ran)"));
        String history = alice.call("", "?history " + mb, Priority.NORMAL, T, null).footer().replyText();
        assertThat(history.lines().filter(l -> l.contains("?cancel #" + id)).findFirst().orElseThrow()).contains("bob");
    }

    @Test
    void aPlotWaitingForItsWorkerIsCancelledAtOnce() throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        // no worker: the plot would wait for the whole timeout; only the cancel ends it in time
        DataVisServer vis = new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis"))
                .withWorker(WorkerMode.NONE).withTimeout(Duration.ofMinutes(10)));
        sys.register(vis);
        String mb = "<DataVisServer>::<localhost>TTY1";
        ClientSocketHandler alice = sys.login("alice");
        Path data = dir.resolve("t.dat");
        Files.writeString(data, "0 1\n1 2\n2 3\n");
        alice.upload(data, "t.dat", null);
        long id = alice.nextId();
        CompletableFuture<OutgoingServerMessage> plot = alice.send(Header.request(id, mb, "vis:t.dat", Priority.NORMAL), null);
        await("the plot to run", () -> status(alice, mb).contains("busy"));
        long t0 = System.nanoTime();
        OutgoingServerMessage c = alice.call("", "?cancel " + id, Priority.NORMAL, T, null);
        assertThat(c.status()).as(c.footer().replyText()).isEqualTo(Status.OK);
        OutgoingServerMessage r = plot.get(20, TimeUnit.SECONDS);
        assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.CANCELLED);
        assertThat(r.footer().replyText()).contains("cancelled by alice").contains("plot of t.dat cancelled");
        assertThat(Duration.ofNanos(System.nanoTime() - t0)).isLessThan(Duration.ofSeconds(10));
    }
}
