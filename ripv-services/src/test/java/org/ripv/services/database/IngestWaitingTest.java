package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.Attachment;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.VehicleEvent;
import org.ripv.service.ReplySink;
import org.ripv.services.ingest.SlocumData;

/**
 * A binary file waiting for its sensor-list cache is not only in the ingest's reply (issue 22):
 * the DatabaseServer MailBox's {@code ?status} names it with the missing CRC for as long as it
 * waits — after a restart of the service too — and its watchers get an INGEST_WAITING event, then
 * INGEST_RELEASED when the cache arrives and the file is ingested.
 */
class IngestWaitingTest {
    static final String SBD = "rosie_713-2019-166-0-157.sbd";
    @TempDir
    Path data;
    final BlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
    final BlockingQueue<ConsoleEntry> events = new LinkedBlockingQueue<>();

    DatabaseServer start() throws Exception {
        DatabaseServer s = new DatabaseServer("testhost", List.of(EmbeddedDatabase.prepare(data, "TTY1")), QueryLimits.defaults());
        s.start();
        s.replyTo(new ReplySink() {
            @Override
            public void reply(OutgoingServiceMessage reply) {
                replies.add(reply);
            }

            @Override
            public void console(List<ConsoleEntry> entries) {
                entries.stream().filter(e -> e.kind() == ConsoleEntry.Kind.EVENT).forEach(events::add);
            }
        });
        return s;
    }

    String ingest(DatabaseServer s, long id, Attachment f) throws Exception {
        s.accept(new IncomingServiceMessage(new Header(id, new IdBadge("123456", "alice"), List.of("operators"),
                s.name().toString(), s.name().mailbox("TTY1").toString(), "ingest " + f.name(), Priority.NORMAL,
                Attachment.bundle(List.of(f)))));
        while (true) {
            OutgoingServiceMessage r = replies.poll(120, TimeUnit.SECONDS);
            assertThat(r).isNotNull();
            if (r.header().messageId() == id && r.status().isFinal()) {
                return r.footer().replyText();
            }
        }
    }

    static String status(DatabaseServer s) {
        MailboxStatus m = s.mailboxes().get(0);
        return m.detail();
    }

    ConsoleEntry event() throws InterruptedException {
        ConsoleEntry e = events.poll(30, TimeUnit.SECONDS);
        assertThat(e).as("an event within 30 s").isNotNull();
        return e;
    }

    @Test
    void theWaitingFileIsInStatusAndEventsUntilItsCacheArrives() throws Exception {
        Path shared = SlocumData.dir();
        Attachment sbd = new Attachment(SBD, Files.readAllBytes(shared.resolve("realtime_raw").resolve(SBD)));
        DatabaseServer s = start();
        try {
            assertThat(status(s)).doesNotContain("waiting");
            assertThat(ingest(s, 1, sbd)).contains(SBD + ": kept, waiting for the sensor list 6b016a2e.cac");
            assertThat(status(s)).contains("waiting for sensor lists: 6b016a2e.cac: " + SBD);
            ConsoleEntry waiting = event();
            assertThat(waiting.event()).isEqualTo(VehicleEvent.INGEST_WAITING);
            assertThat(waiting.mailbox()).isEqualTo(s.name().mailbox("TTY1").toString());
            assertThat(waiting.text()).contains(SBD).contains("6b016a2e.cac");
        } finally {
            s.stop();
        }
        s = start(); // the waiting file is kept on disk: a restarted service still reports it
        try {
            assertThat(status(s)).contains("waiting for sensor lists: 6b016a2e.cac: " + SBD);
            Attachment cac = new Attachment("6b016a2e.cac", Files.readAllBytes(shared.resolve("cac/6b016a2e.cac")));
            assertThat(ingest(s, 2, cac)).contains(SBD + " (waited for 6b016a2e.cac): rosie_713-2019-166-0-157: 365 rows");
            assertThat(status(s)).doesNotContain("waiting");
            ConsoleEntry released = event();
            assertThat(released.event()).isEqualTo(VehicleEvent.INGEST_RELEASED);
            assertThat(released.text()).contains(SBD + " (waited for 6b016a2e.cac): rosie_713-2019-166-0-157: 365 rows");
        } finally {
            s.stop();
        }
    }
}
