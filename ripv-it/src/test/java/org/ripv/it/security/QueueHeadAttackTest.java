package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Priority;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.ServerConfig;
import org.ripv.service.ConsoleTap;

/**
 * Issue 33 item 10: a failing workflow of a low-rights user stayed at the head of a MailBox's
 * queue and blocked the operator's workflow behind it, call after call. Now a failure holds back
 * only its owner's later workflows: the operator's runs on the same call, the failed one keeps its
 * place for its owner's next try.
 */
class QueueHeadAttackTest {
    static final String CLOCK = WebConsoleAttackTest.CLOCK;
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    static Path dir;
    static TestSystem sys;
    static ClockService clock;

    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config).user("otto", "operators").user("dora", "queuers");
        // dora may queue workflows, read the MailBox and send it 'sleep': her workflow's step fails at the vehicle.
        sys.rules("allow @operators * * *", "allow @queuers RIPVServer * ?queue*", "allow @queuers RIPVServer * ?upload*",
                "allow @queuers RIPVServer * ?receipts*", "allow @queuers * * ?read", "allow @queuers ClockService * sleep *");
        clock = new ClockService("localhost");
        sys.register(clock);
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    static String reply(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, p -> { }).footer().replyText();
    }

    static void queue(ClientSocketHandler c, String name, String text) throws Exception {
        Path f = dir.resolve(name);
        Files.writeString(f, text, StandardCharsets.UTF_8);
        c.upload(f, name, null);
        assertThat(reply(c, "?queue add " + CLOCK + " " + name)).contains("queued workflow");
    }

    @Test
    void aLowRightsUsersFailingWorkflowDoesNotBlockTheOperators() throws Exception {
        ClientSocketHandler dora = sys.login("dora");
        ClientSocketHandler otto = sys.login("otto");
        queue(dora, "doras.wf", "workflow once\nsend sleep forever\n");
        queue(otto, "ottos.wf", "workflow once\nsend time\nnotify \"otto's workflow ran\"\n");

        ConsoleTap.publish(clock, ConsoleEntry.event(CLOCK, VehicleEvent.SURFACED, "the vehicle calls", null, null));
        long end = System.nanoTime() + T.toNanos();
        String receipts;
        while (!(receipts = reply(otto, "?receipts " + CLOCK)).contains("'ottos.wf'")
                || !receipts.matches("(?s).*'ottos.wf'.*result: (DONE|FAILED|CUT).*")) {
            assertThat(System.nanoTime()).as("otto's workflow runs on this call:\n" + receipts).isLessThan(end);
            Thread.sleep(100);
        }
        assertThat(receipts).contains("'doras.wf' of dora").contains("result: FAILED");
        assertThat(receipts).matches("(?s).*'ottos.wf' of otto.*result: DONE.*");
        // dora's failed workflow keeps its place for her next try; otto's once-workflow is done and gone.
        String queue = reply(otto, "?queue " + CLOCK);
        assertThat(queue).contains("doras.wf").doesNotContain("ottos.wf");
        dora.close();
        otto.close();
    }
}
