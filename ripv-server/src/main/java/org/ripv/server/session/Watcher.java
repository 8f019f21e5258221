package org.ripv.server.session;

import java.io.IOException;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;

/**
 * One client watching one MailBox. Keeps at most {@link #MAX_IN_FLIGHT} pushes queued on the
 * client's connection and holds what arrives beyond that in a bounded backlog; when the backlog overflows, the oldest
 * entries go and the next push starts with a marker saying how many, and from when, so the
 * client can fetch them with {@code ?history}. Nothing here blocks: a client that stops reading
 * costs the vehicle, the service and the other watchers nothing but this backlog.
 */
final class Watcher {
    /** Entries held for a watcher whose connection is busy before the oldest are skipped. */
    static final int MAX_BACKLOG = 2_000;
    /** The most entries in one push. */
    static final int MAX_BATCH = 500;
    /**
     * Pushes queued on the connection and not yet written, beyond which entries wait in the
     * backlog. Up-to-date watchers queue the push shared by all (encoded once); a writer that
     * finds several waiting sends them with one flush, so a busy server coalesces by itself.
     */
    static final int MAX_IN_FLIGHT = 32;

    final String clientId;
    final String user;
    final String mailbox;
    /** Which of the hub's fan-out threads offers this watcher its pushes: 0 is the taking thread (ConsoleHub). */
    final int shard;
    private final Outlet outlet;
    /** What runs when a push has been written: one object for every push, not one each. */
    private final Runnable onWritten = this::written;
    private final ArrayDeque<ConsoleEntry> backlog = new ArrayDeque<>();
    private long skipped;
    private long skippedFrom;
    private long totalSkipped;
    private int inFlight;
    private volatile boolean stopped;

    Watcher(String clientId, String user, String mailbox, Outlet outlet, int shard) {
        this.clientId = clientId;
        this.user = user;
        this.mailbox = mailbox;
        this.outlet = outlet;
        this.shard = shard;
    }

    /**
     * A push built once for every watcher that is up to date, and encoded once when the first
     * socket client asks (web pages write their own JSON: PushJson).
     */
    static final class Shared implements Supplier<byte[]> {
        private static final byte[] NONE = new byte[0];
        final OutgoingServerMessage message;
        private final ConsoleHub.Encoder encoder;
        private volatile byte[] frame;

        Shared(OutgoingServerMessage message, ConsoleHub.Encoder encoder) {
            this.message = message;
            this.encoder = encoder;
        }

        /** The encoded push, or null when it is too large for one frame (each writer then reports it). */
        @Override
        public byte[] get() {
            byte[] f = frame;
            if (f == null) {
                synchronized (this) {
                    f = frame;
                    if (f == null) {
                        try {
                            f = encoder.encode(message);
                        } catch (IOException x) {
                            f = NONE;
                        }
                        frame = f;
                    }
                }
            }
            return f == NONE ? null : f;
        }
    }

    private static final Supplier<byte[]> NOT_ENCODED = () -> null;

    /** Takes new entries; pushes at once if nothing is in flight. The shared push is used when it can be. */
    void offer(List<ConsoleEntry> entries, Shared shared) {
        Shared now = null;
        synchronized (this) {
            if (stopped) {
                return;
            }
            if (inFlight < MAX_IN_FLIGHT && backlog.isEmpty() && skipped == 0 && shared != null) {
                inFlight++;
                now = shared;
            } else {
                for (ConsoleEntry e : entries) {
                    if (backlog.size() == MAX_BACKLOG) {
                        ConsoleEntry gone = backlog.removeFirst();
                        if (skipped == 0) {
                            skippedFrom = gone.time();
                        }
                        skipped++;
                        totalSkipped++;
                    }
                    backlog.addLast(e);
                }
            }
        }
        if (now != null) {
            send(now.message, now);
        } else {
            pump();
        }
    }

    /** Sends the next batch from the backlog if nothing is in flight. */
    private void pump() {
        OutgoingServerMessage next;
        synchronized (this) {
            if (stopped || inFlight >= MAX_IN_FLIGHT || backlog.isEmpty() && skipped == 0) {
                return;
            }
            List<ConsoleEntry> batch = new ArrayList<>(Math.min(MAX_BATCH + 1, backlog.size() + 1));
            long lost = skipped;
            if (lost > 0) {
                batch.add(new ConsoleEntry(System.currentTimeMillis(), mailbox, ConsoleEntry.Kind.LINE, "",
                        "[" + lost + " lines skipped: this client read too slowly; ?history " + mailbox + " --since "
                                + Instant.ofEpochMilli(skippedFrom) + " fetches them]", null, null, null));
                skipped = 0;
            }
            while (batch.size() < MAX_BATCH && !backlog.isEmpty()) {
                batch.add(backlog.removeFirst());
            }
            next = message(mailbox, batch, lost);
            inFlight++;
        }
        send(next, NOT_ENCODED);
    }

    private void send(OutgoingServerMessage m, Supplier<byte[]> frame) {
        if (!outlet.push(m, frame, onWritten)) {
            synchronized (this) {
                inFlight--; // the connection is closing, or full of replies: the next entry tries again
            }
        }
    }

    private void written() {
        synchronized (this) {
            inFlight--;
            if (backlog.isEmpty() && skipped == 0) {
                return; // up to date: nothing to pump (the common case, once per push)
            }
        }
        pump();
    }

    void stop() {
        stopped = true;
        synchronized (this) {
            backlog.clear();
        }
    }

    /**
     * Ends this watch because the user may no longer read the MailBox: what waits for it is
     * dropped (it may not read that either) and the client gets one last push, an ERROR
     * {@code FORBIDDEN} whose batch holds one line saying why, after which nothing more comes.
     */
    void end(String why) {
        stop();
        String text = "watch of " + mailbox + " ended: " + why;
        ConsoleEntry line = new ConsoleEntry(System.currentTimeMillis(), mailbox, ConsoleEntry.Kind.LINE, "", "[" + text + "]",
                null, null, null);
        OutgoingServerMessage m = message(mailbox, List.of(line), 0);
        outlet.send(new OutgoingServerMessage(m.header(), Footer.error(Ids.FID_CONSOLE,
                ErrorCode.FORBIDDEN, text).withResult(m.footer().result())));
    }

    synchronized int backlog() {
        return backlog.size();
    }

    synchronized long totalSkipped() {
        return totalSkipped;
    }

    /** A push: message id 0, status PROGRESS, FID_CONSOLE, the entries in a {@link ConsoleBatch}. */
    static OutgoingServerMessage message(String mailbox, List<ConsoleEntry> entries, long skipped) {
        Header h = new Header(0, IdBadge.SERVER, List.of(), "", mailbox, "?watch " + mailbox, Priority.NORMAL, null);
        return new OutgoingServerMessage(h, Footer.progress(Ids.FID_CONSOLE, "", new ConsoleBatch(mailbox, entries, skipped, false)));
    }
}
