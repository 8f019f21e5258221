package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.naming.Handles;

/** Drives a DataVisServer in-process, the way the RMI adapter does, and collects its replies by message id. */
final class VisHarness implements AutoCloseable {
    private static final AtomicLong IDS = new AtomicLong(1000);
    final DataVisServer service;
    private final ConcurrentHashMap<Long, BlockingQueue<OutgoingServiceMessage>> replies = new ConcurrentHashMap<>();

    VisHarness(DataVisServer.Config config) throws Exception {
        service = new DataVisServer("testhost", config);
        service.start();
        service.replyTo(r -> queue(r.header().messageId()).add(r));
    }

    private BlockingQueue<OutgoingServiceMessage> queue(long id) {
        return replies.computeIfAbsent(id, k -> new LinkedBlockingQueue<>());
    }

    String mailbox() {
        return service.name().mailbox(Handles.platformDefault()).toString();
    }

    /** Sends a command with an optional attachment; returns its message id. */
    long send(String command, String fileName, byte[] data) {
        long id = IDS.incrementAndGet();
        Attachment a = fileName == null ? null : new Attachment(fileName, data);
        service.accept(new IncomingServiceMessage(new Header(id, new IdBadge("123456", "alice"), List.of(),
                service.name().toString(), mailbox(), command, Priority.NORMAL, a)));
        return id;
    }

    long send(String command, String fileName, String text) {
        return send(command, fileName, text == null ? null : text.getBytes(StandardCharsets.UTF_8));
    }

    /** The final (OK or ERROR) reply to message {@code id}, skipping PROGRESS. */
    OutgoingServiceMessage finalReply(long id, long seconds) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (true) {
            OutgoingServiceMessage m = queue(id).poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS);
            if (m == null) {
                throw new AssertionError("no final reply to #" + id + " within " + seconds + " s");
            }
            if (m.footer().status() != Status.PROGRESS) {
                return m;
            }
        }
    }

    /** Waits for a PROGRESS reply to message {@code id} (the plot has been handed to the worker). */
    OutgoingServiceMessage awaitProgress(long id, long seconds) throws InterruptedException {
        OutgoingServiceMessage m = queue(id).poll(seconds, TimeUnit.SECONDS);
        assertThat(m).as("a reply to #" + id).isNotNull();
        assertThat(m.footer().status()).as(m.footer().replyText()).isEqualTo(Status.PROGRESS);
        return m;
    }

    /** {@code ?cancel} as the server passes it on. */
    boolean cancel(long id) {
        return service.cancel(mailbox(), "123456", id);
    }

    OutgoingServiceMessage run(String command, String fileName, String text) throws InterruptedException {
        return finalReply(send(command, fileName, text), 60);
    }

    /** Files left in the work directory. */
    List<String> leftovers() throws IOException {
        try (Stream<Path> s = Files.list(service.workDir())) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    static BufferedImage decode(byte[] jpeg) throws IOException {
        assertThat(jpeg).hasSizeGreaterThan(100);
        assertThat(jpeg[0] & 0xff).isEqualTo(0xFF);
        assertThat(jpeg[1] & 0xff).isEqualTo(0xD8);
        BufferedImage img = ImageIO.read(new ByteArrayInputStream(jpeg));
        assertThat(img).as("a decodable JPEG").isNotNull();
        return img;
    }

    @Override
    public void close() {
        service.stop();
    }
}
