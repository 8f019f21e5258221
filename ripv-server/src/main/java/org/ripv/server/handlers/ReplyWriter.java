package org.ripv.server.handlers;

import java.io.BufferedOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.wire.FrameCodec;
import org.ripv.wire.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One client's reply queue and the only thread that writes its socket. The thread runs only
 * while replies wait: it ends after {@link #IDLE_MILLIS} with nothing to send and the next reply
 * starts another, so an idle client costs no writer thread (docs/performance.md). A lock makes
 * sure at most one runs and a reply queued as it ends is never stranded.
 */
final class ReplyWriter {
    private static final Logger log = LoggerFactory.getLogger(ReplyWriter.class);
    /** How long the writer thread waits for more replies before it ends. */
    static final long IDLE_MILLIS = 5_000;

    private static final OutgoingServerMessage POISON = new OutgoingServerMessage(
            Header.request(0, "", "", null), Footer.unanswered());

    private final String clientId;
    private final FrameCodec codec;
    private final Runnable closer;
    /** Linked, not an array: an idle client must not hold thousands of empty slots. */
    private final BlockingQueue<OutgoingServerMessage> replies;
    private final int capacity;
    /** A push: its frame if encoded once for many clients (else null), and what to run once it went out. */
    private record Push(byte[] frame, Runnable written) {}

    /** Pushes whose sender wants to hear when they went out (console watchers pace themselves by it). */
    private final java.util.Map<OutgoingServerMessage, Push> afterWrite = new java.util.concurrent.ConcurrentHashMap<>();
    private final Object lock = new Object();
    private boolean running;
    private boolean stopped;
    private DataOutputStream out;

    /** @param closer closes the connection after a write failed or the last reply went out */
    ReplyWriter(String clientId, FrameCodec codec, int capacity, Runnable closer) {
        this.clientId = clientId;
        this.codec = codec;
        this.closer = closer;
        this.replies = new LinkedBlockingQueue<>(capacity);
        this.capacity = capacity;
    }

    /** The socket may be written now (the greeting is done): replies queued so far go out. */
    void open(OutputStream socketOut, int buffer) {
        synchronized (lock) {
            out = new DataOutputStream(new BufferedOutputStream(socketOut, buffer));
        }
        startIfNeeded();
    }

    /** Queues a reply; false when the queue is full (the client is not reading). */
    boolean offer(OutgoingServerMessage reply) {
        if (!replies.offer(reply)) {
            return false;
        }
        startIfNeeded();
        return true;
    }

    /**
     * Queues an unasked message (a console push); {@code written} runs on the writer thread once
     * it has been written and flushed. {@code frame}, when not null, is the message already
     * encoded. False when the queue is more than half full (pushes never crowd out replies).
     */
    boolean push(OutgoingServerMessage message, byte[] frame, Runnable written) {
        if (replies.remainingCapacity() < capacity / 2) {
            return false;
        }
        afterWrite.put(message, new Push(frame, written));
        if (!replies.offer(message)) {
            afterWrite.remove(message);
            return false;
        }
        startIfNeeded();
        return true;
    }

    /** Queues a last reply, after which the writer closes the connection; false when full. */
    boolean offerLast(OutgoingServerMessage reply) {
        if (!replies.offer(reply) || !replies.offer(POISON)) {
            return false;
        }
        startIfNeeded();
        return true;
    }

    /** Drops what waits and ends the writer (the connection is closing). */
    void stop() {
        synchronized (lock) {
            stopped = true;
        }
        replies.clear();
        afterWrite.clear();
        replies.offer(POISON);
    }

    private void startIfNeeded() {
        synchronized (lock) {
            if (running || out == null || stopped || replies.isEmpty()) {
                return;
            }
            running = true;
        }
        Thread t = new Thread(this::run, "ripv-socket-writer-" + clientId);
        t.setDaemon(true);
        t.start();
    }

    private void run() {
        boolean close = true;
        java.util.List<Runnable> flushed = new java.util.ArrayList<>();
        try {
            while (true) {
                OutgoingServerMessage m = replies.poll(IDLE_MILLIS, TimeUnit.MILLISECONDS);
                if (m == null) {
                    synchronized (lock) {
                        if (replies.isEmpty()) {
                            running = false; // all is flushed; the next reply starts another writer
                            close = stopped;
                            return;
                        }
                    }
                    continue;
                }
                if (m == POISON) {
                    out.flush();
                    return;
                }
                Push push = afterWrite.remove(m);
                if (push != null) {
                    flushed.add(push.written());
                }
                if (push != null && push.frame() != null) {
                    out.writeInt(push.frame().length);
                    out.write(push.frame());
                } else {
                    write(m);
                }
                if (replies.isEmpty()) {
                    out.flush();
                    flushed.forEach(Runnable::run);
                    flushed.clear();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            log.debug("client {}: write failed: {}", clientId, e.toString());
        } finally {
            if (close) {
                closer.run();
            }
        }
    }

    private void write(OutgoingServerMessage m) throws IOException {
        try {
            codec.writeNoFlush(out, m);
        } catch (ProtocolException tooLarge) {
            // Nothing was written yet: tell the client instead of cutting it off. A progress
            // report is only dropped, so the request still ends in its one real final reply.
            log.warn("client {}: reply to #{} not sent: {}", clientId, m.header().messageId(), tooLarge.getMessage());
            if (m.status().isFinal()) {
                codec.writeNoFlush(out, new OutgoingServerMessage(m.header(), Footer.error(m.footer().serviceId(),
                        ErrorCode.TOO_LARGE, "the reply was too large to send (" + tooLarge.getMessage()
                                + "); ask for less, e.g. fewer rows").via("RIPVServer")));
            }
        }
    }
}
