package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.TablePages;
import org.ripv.messages.TableResult;
import org.ripv.service.RIPVService;

/**
 * Sends requests to a started service in-process (the path the RMI adapter uses) and waits for the
 * final reply, with a table's pages joined into it as a client does ({@link TablePages}).
 */
final class ServiceHarness {
    private final RIPVService service;
    private final BlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
    private final AtomicLong ids = new AtomicLong();

    ServiceHarness(RIPVService service) {
        this.service = service;
        service.replyTo(replies::add);
    }

    /** Sends {@code command} to MailBox {@code handle} as {@code user} with {@code roles}; returns the final reply. */
    OutgoingServiceMessage send(String handle, String command, String user, List<String> roles) throws InterruptedException {
        long id = ids.incrementAndGet();
        String mailbox = service.name().mailbox(handle).toString();
        service.accept(new IncomingServiceMessage(new Header(id, new IdBadge("123456", user), roles,
                service.name().toString(), mailbox, command, Priority.NORMAL, null)));
        TablePages pages = new TablePages();
        while (true) {
            OutgoingServiceMessage r = replies.poll(120, TimeUnit.SECONDS);
            assertThat(r).as("a reply to '" + command + "' within 120 s").isNotNull();
            if (r.header().messageId() == id && TablePages.isPage(r.footer())) {
                pages.add((TableResult) r.footer().result());
            } else if (r.header().messageId() == id && r.status().isFinal()) {
                return new OutgoingServiceMessage(r.header(), pages.join(r.footer()));
            }
        }
    }

    OutgoingServiceMessage send(String handle, String command) throws InterruptedException {
        return send(handle, command, "alice", List.of("operators"));
    }
}
