package org.ripv.server.handlers;

import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.wire.FrameCodec;
import org.ripv.wire.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One client's reply queue. Nothing writes the socket but the {@link WriterPool}'s worker that
 * holds this writer: {@link #scheduled} is true from the moment a reply finds the queue without a
 * worker until a worker has written everything and found the queue empty, so at most one thread
 * writes at a time and a reply queued as a worker finishes is never stranded. An idle client
 * costs no writer thread (docs/performance.md). The socket never blocks a worker: while its
 * connection holds more than it can send ({@code backedUp}), the writer leaves the rest in its
 * bounded queue and is scheduled again when the connection has drained.
 */
final class ReplyWriter {
    private static final Logger log = LoggerFactory.getLogger(ReplyWriter.class);
    /** How long a worker that stays with one slow client waits for more before it ends. */
    static final long IDLE_MILLIS = 5_000;
    /** The most messages one turn writes before the worker moves on to other clients. */
    static final int MAX_PER_TURN = 256;

    /** What waits: a reply, or a push with its frame if encoded once for many clients (else null) and what to run once it went out. */
    private record Item(OutgoingServerMessage message, byte[] frame, Runnable written) {}

    private static final Item POISON = new Item(null, null, null);

    private final String clientId;
    private final FrameCodec codec;
    private final Runnable closer;
    private final WriterPool pool;
    /** Linked, not an array: an idle client must not hold thousands of empty slots. */
    private final BlockingQueue<Item> replies;
    private final int capacity;
    private final Object lock = new Object();
    private boolean scheduled;
    private boolean stopped;
    private boolean ended;
    private DataOutputStream out;
    private BooleanSupplier backedUp = () -> false;
    private final List<Runnable> flushed = new ArrayList<>();

    /** @param closer closes the connection after a write failed or the last reply went out */
    ReplyWriter(String clientId, FrameCodec codec, int capacity, WriterPool pool, Runnable closer) {
        this.clientId = clientId;
        this.codec = codec;
        this.closer = closer;
        this.pool = pool;
        this.replies = new LinkedBlockingQueue<>(capacity);
        this.capacity = capacity;
    }

    /**
     * The socket may be written now (the greeting is done): replies queued so far go out.
     *
     * @param socketOut gathers what is written until a flush
     * @param full      true while the connection holds more unsent bytes than it should
     */
    void open(OutputStream socketOut, BooleanSupplier full) {
        synchronized (lock) {
            backedUp = full;
            out = new DataOutputStream(socketOut);
        }
        scheduleIfNeeded();
    }

    /** The connection sent what it held: replies that waited for it go out. */
    void drained() {
        scheduleIfNeeded();
    }

    /** Queues a reply; false when the queue is full (the client is not reading). */
    boolean offer(OutgoingServerMessage reply) {
        if (!replies.offer(new Item(reply, null, null))) {
            return false;
        }
        scheduleIfNeeded();
        return true;
    }

    /**
     * Queues an unasked message (a console push); {@code written} runs on the writing thread once
     * it has been written and flushed. {@code frame}, when not null, is the message already
     * encoded. False when the queue is more than half full (pushes never crowd out replies).
     */
    boolean push(OutgoingServerMessage message, byte[] frame, Runnable written) {
        if (replies.remainingCapacity() < capacity / 2) {
            return false;
        }
        if (!replies.offer(new Item(message, frame, written))) {
            return false;
        }
        scheduleIfNeeded();
        return true;
    }

    /** Queues a last reply, after which the writer closes the connection; false when full. */
    boolean offerLast(OutgoingServerMessage reply) {
        if (!replies.offer(new Item(reply, null, null)) || !replies.offer(POISON)) {
            return false;
        }
        scheduleIfNeeded();
        return true;
    }

    /** Drops what waits and ends the writer (the connection is closing). */
    void stop() {
        synchronized (lock) {
            stopped = true;
        }
        replies.clear();
    }

    private void scheduleIfNeeded() {
        synchronized (lock) {
            if (scheduled || out == null || stopped || replies.isEmpty() || backedUp.getAsBoolean()) {
                return;
            }
            scheduled = true;
        }
        pool.ready(this);
    }

    /**
     * One worker's turn: writes what waits (at most {@link #MAX_PER_TURN} messages) with one flush.
     * True when more waits and this writer is still scheduled (the caller puts it back in line or
     * keeps writing it); false when its queue was empty or the connection ended.
     */
    boolean turn() {
        return write(replies.poll());
    }

    /**
     * Writes this client alone, on the calling thread, until it has had nothing to write for
     * {@link #IDLE_MILLIS} (a worker that left the pool because this client was slow).
     */
    void dedicated() throws InterruptedException {
        while (write(replies.poll(IDLE_MILLIS, TimeUnit.MILLISECONDS))) {
            // each round blocks in poll, never spins; a backed-up connection ends the round
        }
    }

    /** Writes first and whatever else waits, flushes once; then as {@link #turn()}. */
    private boolean write(Item first) {
        boolean close = true;
        try {
            Item m = first;
            int n = 0;
            while (m != null) {
                if (m == POISON) {
                    out.flush();
                    afterFlush();
                    return end();
                }
                if (m.written() != null) {
                    flushed.add(m.written());
                }
                if (m.frame() != null) {
                    out.writeInt(m.frame().length);
                    out.write(m.frame());
                } else {
                    encode(m.message());
                }
                m = ++n < MAX_PER_TURN && !backedUp.getAsBoolean() ? replies.poll() : null;
            }
            if (n > 0) {
                out.flush();
                afterFlush();
            }
            close = false;
        } catch (IOException e) {
            log.debug("client {}: write failed: {}", clientId, e.toString());
        } catch (RuntimeException e) {
            log.error("client {}: writing failed", clientId, e);
        } finally {
            if (close) {
                end();
            }
        }
        synchronized (lock) {
            if (stopped || replies.isEmpty() || backedUp.getAsBoolean()) {
                scheduled = false; // all is flushed; the next reply (or the connection draining) schedules this writer again
                return false;
            }
            return true;
        }
    }

    private void afterFlush() {
        for (Runnable r : flushed) {
            r.run();
        }
        flushed.clear();
    }

    /** The last reply went out or a write failed: the connection closes, and nothing is written again. */
    private boolean end() {
        synchronized (lock) {
            if (ended) {
                return false;
            }
            ended = true;
            stopped = true;
        }
        // On this writer, as part of its turn (closing never waits for the peer: the close_notify
        // goes only if the socket takes it at once). Closing on threads of their own let a log-in
        // flood reconnect faster: LoginFloodAttackTest.
        closer.run();
        return false;
    }

    private void encode(OutgoingServerMessage m) throws IOException {
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
