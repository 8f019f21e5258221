package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.service.RIPVService;

/**
 * Drives a service in-process the way the RMI adapter does: {@code accept} a request and
 * collect every reply (PROGRESS ones too) until the final one.
 */
public final class ServiceProbe {
    private final RIPVService service;
    private final LinkedBlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
    private final AtomicLong ids = new AtomicLong();
    /** Called with each PROGRESS reply as it is collected (a test can inject a fault mid-transfer). */
    public volatile java.util.function.Consumer<OutgoingServiceMessage> onProgress = m -> { };

    /** Every console entry the service published, in order. */
    public final java.util.concurrent.CopyOnWriteArrayList<org.ripv.messages.ConsoleEntry> console =
            new java.util.concurrent.CopyOnWriteArrayList<>();

    public ServiceProbe(RIPVService service) {
        this.service = service;
        service.replyTo(new org.ripv.service.ReplySink() {
            @Override
            public void reply(OutgoingServiceMessage reply) {
                replies.add(reply);
            }

            @Override
            public void console(List<org.ripv.messages.ConsoleEntry> entries) {
                console.addAll(entries);
            }
        });
    }

    /** The console entries of one kind, for one handle. */
    public List<org.ripv.messages.ConsoleEntry> console(String handle, org.ripv.messages.ConsoleEntry.Kind kind) {
        String address = service.name().mailbox(handle).toString();
        return console.stream().filter(e -> e.mailbox().equals(address) && e.kind() == kind).toList();
    }

    /** The texts of the LINE entries of one handle. */
    public List<String> lines(String handle) {
        return console(handle, org.ripv.messages.ConsoleEntry.Kind.LINE).stream()
                .map(org.ripv.messages.ConsoleEntry::text).toList();
    }

    /** The events of one handle, in order. */
    public List<org.ripv.messages.ConsoleEntry> events(String handle) {
        return console(handle, org.ripv.messages.ConsoleEntry.Kind.EVENT);
    }

    /** What one request produced. */
    public record Answer(List<OutgoingServiceMessage> progress, OutgoingServiceMessage last) {
        public String text() {
            return last.footer().replyText();
        }

        public boolean ok() {
            return last.footer().status() == Status.OK;
        }
    }

    public Answer send(String handle, String command, Duration timeout) throws InterruptedException {
        return send(handle, command, null, timeout);
    }

    public Answer send(String handle, String command, Attachment attachment, Duration timeout)
            throws InterruptedException {
        long id = ids.incrementAndGet();
        service.accept(new IncomingServiceMessage(new Header(id, new IdBadge("123456", "alice"), List.of(),
                service.name().toString(), service.name().mailbox(handle).toString(), command, Priority.NORMAL,
                attachment)));
        List<OutgoingServiceMessage> progress = new ArrayList<>();
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            OutgoingServiceMessage m = replies.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS);
            assertNotNull(m, "no final reply to '" + command + "' within " + timeout);
            if (m.header().messageId() != id) {
                continue;
            }
            if (m.footer().status() == Status.PROGRESS) {
                progress.add(m);
                onProgress.accept(m);
            } else {
                return new Answer(progress, m);
            }
        }
    }

    /** The message id of the last request sent (a test cancels it while {@link #send} waits in another thread). */
    public long lastId() {
        return ids.get();
    }

    /** {@code ?cancel} as the server passes it on: true when the handler accepted. */
    public boolean cancel(String handle, long messageId) {
        return service.cancel(service.name().mailbox(handle).toString(), "123456", messageId);
    }

    public MailboxStatus status(String handle) {
        String address = service.name().mailbox(handle).toString();
        return service.mailboxes().stream().filter(s -> s.address().equals(address)).findFirst().orElseThrow();
    }
}
