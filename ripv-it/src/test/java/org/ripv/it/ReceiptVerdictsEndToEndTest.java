package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.function.Predicate;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.serial.CallSettings;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.VehicleLink;

/**
 * Issue 24, item 5: receipts tell the truth. The glider simulator, launched as its own process,
 * calls a SerialPortServer's listen:// link; a queued workflow asks for a file the vehicle does not
 * have, fetches a DBA file the database refuses and one it takes. With {@code continue-on-error} the
 * run ends DONE_WITH_ERRORS (receipt, event), its notify says what happened. Issue 32, item 10: the
 * refused file is a fetch that worked, a {@code note:} in the step's output, not a failed step.
 */
class ReceiptVerdictsEndToEndTest {
    static final Path SLOCUM = Path.of("../ripv-services/src/test/resources/slocum");
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path dir;
    TestSystem sys;
    Process simulator;

    @AfterEach
    void stop() throws Exception {
        SimulatorProcess.stop(simulator);
        if (sys != null) {
            sys.close();
        }
    }

    private static String ok(ClientSocketHandler c, String body) throws Exception {
        OutgoingServerMessage r = c.call("", body, Priority.NORMAL, T, null);
        assertThat(r.status()).as(body + " -> " + r.footer().replyText()).isEqualTo(Status.OK);
        return r.footer().replyText();
    }

    private static String await(ClientSocketHandler c, String body, Predicate<String> done) throws Exception {
        long end = System.nanoTime() + Duration.ofSeconds(120).toNanos();
        String last = "";
        while (System.nanoTime() < end) {
            last = c.call("", body, Priority.NORMAL, T, null).footer().replyText();
            if (done.test(last)) {
                return last;
            }
            Thread.sleep(200);
        }
        throw new AssertionError("gave up waiting on '" + body + "'; last reply:\n" + last);
    }

    private void upload(ClientSocketHandler c, String name, String text) throws Exception {
        Path local = Files.createDirectories(dir.resolve("local")).resolve(name);
        Files.writeString(local, text, StandardCharsets.UTF_8);
        c.upload(local, name, null);
    }

    @Test
    void aRefusedIngestIsANoteOfAnOkFetchAndContinueOnErrorEndsDoneWithErrors() throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        LinkSettings link = LinkSettings.defaults("listen://127.0.0.1:0").withIdleTimeout(Duration.ofSeconds(1))
                .withYmodem(SerialEndToEndTest.YMODEM);
        SerialPortServer serial = SerialPortServer.withCalls("localhost",
                List.of(new VehicleLink(link, CallSettings.defaults().withName("ru29"))), null, false, dir.resolve("work"));
        sys.register(serial);
        sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                QueryLimits.defaults()));
        String mb = "<SerialPortServer>::<localhost>ru29";
        ClientSocketHandler alice = sys.login("alice");
        upload(alice, "night.wf", """
                ymodem:get missing.mrg continue-on-error
                ymodem:get short_header.mrg
                ymodem:get cp_388_2016_012_0_0.mrg
                notify "ru29: {fetched} fetched, {ingested} ingested, {failed} step(s) failed"
                """);
        upload(alice, "strict.wf", "ymodem:get short_header.mrg all\nnotify 'the refused file was fetched'\n");
        ok(alice, "?queue add " + mb + " night.wf");
        ok(alice, "?queue add " + mb + " strict.wf");

        // the simulator, launched as the ripv launcher does, calls in with the Slocum files on board
        Path glider = Files.createDirectories(dir.resolve("glider"));
        Files.copy(SLOCUM.resolve("short_header.mrg"), glider.resolve("short_header.mrg"));
        Files.copy(SLOCUM.resolve("cp_388_2016_012_0_0.mrg"), glider.resolve("cp_388_2016_012_0_0.mrg"));
        simulator = SimulatorProcess.start(dir.resolve("simulator.log"), List.of("--call", "127.0.0.1:"
                + serial.listenPort("ru29"), "--name", "ru29", "--surface-seconds", "120", "--dive-seconds", "5",
                "--dir", glider.toString()));

        // its verdict, not "result: RUNNING", which a loaded machine shows while its last step ends
        String receipts = await(alice, "?receipts " + mb, r -> r.contains("'strict.wf'")
                && r.substring(r.indexOf("'strict.wf'")).contains("result: ")
                && !r.substring(r.indexOf("'strict.wf'")).contains("result: RUNNING"));
        String night = receipts.substring(receipts.indexOf("receipt: workflow 1"), receipts.indexOf("receipt: workflow 2"));
        String strict = receipts.substring(receipts.indexOf("receipt: workflow 2"));
        assertThat(night).as(night)
                .contains("step 1/4 (line 1) ymodem:get missing.mrg: FAILED (continue-on-error)")
                .contains("step 2/4 (line 2) ymodem:get short_header.mrg: OK")
                .contains("fetched 1, ingested 0 into <DatabaseServer>")
                .contains("note: ru29@")
                .contains("short_header.mrg: refused, nothing stored: line 11")
                .contains("step 3/4 (line 3) ymodem:get cp_388_2016_012_0_0.mrg: OK")
                .contains("step 4/4 (line 4) notify ru29: {fetched} fetched, {ingested} ingested, {failed} step(s) failed: OK")
                .contains("output: ru29: 2 fetched, 1 ingested, 1 step(s) failed")
                .contains("done: fetched 2, ingested 1, 1 step(s) failed")
                .contains("result: DONE_WITH_ERRORS")
                .contains("error: 1 step(s) failed (continue-on-error)")
                .doesNotContain("DATABASE_ERROR")
                .doesNotContain("result: DONE at");
        assertThat(night).containsPattern("file ru29\\S*/short_header.mrg \\d+ bytes sha256"); // fetched, kept, recorded
        assertThat(strict).as(strict)
                .contains("step 1/2 (line 1) ymodem:get short_header.mrg all: OK")
                .contains("note: ")
                .contains("output: the refused file was fetched")
                .contains("result: DONE");
        String history = await(alice, "?history " + mb, h -> h.contains("'strict.wf'"));
        assertThat(history).contains("* WORKFLOW_DONE_WITH_ERRORS workflow 1 'night.wf': done_with_errors: 1 step(s) failed")
                .contains("'night.wf': ru29: 2 fetched, 1 ingested, 1 step(s) failed")
                .doesNotContain("WORKFLOW_FAILED");
        // the database said it per file, as an event of its MailBox
        String dbHistory = await(alice, "?history <DatabaseServer>::<localhost>TTY1", h -> h.contains("INGEST_REFUSED"));
        assertThat(dbHistory).contains("short_header.mrg: refused, nothing stored");
        // both once workflows reached their end and left the queue
        String queue = ok(alice, "?queue " + mb);
        assertThat(queue).doesNotContain("night.wf").doesNotContain("strict.wf");
    }
}
