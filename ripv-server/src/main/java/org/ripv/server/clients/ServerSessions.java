package org.ripv.server.clients;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ScheduledExecutorService;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.SessionOptions;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.notify.Notifier;
import org.ripv.server.notify.NotifyCommands;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.requests.ServerReplies;
import org.ripv.server.session.ConsoleCommands;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.session.Outlet;
import org.ripv.server.session.Rights;
import org.ripv.server.store.StateStore;
import org.ripv.server.surfacing.SurfacingCommands;
import org.ripv.server.surfacing.Surfacings;
import org.ripv.wire.FrameCodec;

/**
 * The server's vehicle sessions wired together (docs/sessions.md): the console hub with its
 * transcripts, the notifier, and the commands that reach them; RIPVServer only calls in here.
 */
public final class ServerSessions implements AutoCloseable {
    /** A MailBox's transcript keeps at most this many files' worth of entries a day (docs/security.md). */
    static final int TRANSCRIPT_FILES_A_DAY = 4;
    private final ConsoleHub console;
    private final Notifier notifier;
    private final ConsoleCommands consoleCommands;
    private final NotifyCommands notifyCommands;
    private final Surfacings surfacings;
    private final SurfacingCommands surfacingCommands;
    private LockExpiries lockExpiries;

    public ServerSessions(Path dataDir, StateStore store, SessionOptions options, Supplier<PermitFile> permits,
                   Function<String, Optional<SocketHandler>> clients, FrameCodec codec) throws IOException {
        // A MailBox's transcript keeps at most four files' worth a day (256 MiB by default).
        console = new ConsoleHub(dataDir.resolve("transcripts"), store, options.keepDays(),
                options.transcriptFileBytes() * TRANSCRIPT_FILES_A_DAY, codec::encode);
        notifier = new Notifier(store, permits, options.smtp(),
                options.notifyBackoff(), options.notifyTimeout(), options.webhooks());
        console.onEvent(notifier::accept);
        consoleCommands = new ConsoleCommands(console, permits, id -> clients.apply(id).map(this::outlet),
                ServerReplies.SERVICE);
        notifyCommands = new NotifyCommands(notifier, ServerReplies.SERVICE);
        // Every surface dialog becomes a call record, alerts and overdue calls (docs/surfacings.md).
        surfacings = new Surfacings(store, dataDir.resolve("surfacing-alerts.conf"), console::serverEntry);
        console.onTaken(surfacings::accept);
        surfacingCommands = new SurfacingCommands(surfacings, permits, ServerReplies.SERVICE);
    }

    /** Counts the replies a watch sends itself (they do not pass the Post Office's outbox) as final (issue 33 item 10). */
    public void countRepliesIn(WaitingRequests requests) {
        this.waiting = requests;
    }

    private volatile WaitingRequests waiting;

    private Outlet outlet(SocketHandler h) {
        return new Outlet() {
            @Override
            public boolean push(OutgoingServerMessage message, Supplier<byte[]> frame, Runnable written) {
                return h.push(message, frame, written);
            }

            @Override
            public void send(OutgoingServerMessage reply) {
                WaitingRequests w = waiting;
                if (w != null && reply.footer().status() != Status.PROGRESS) {
                    w.done(h.clientId(), reply.header());
                }
                h.send(reply);
            }

            @Override
            public boolean isOpen() {
                return !h.isClosed();
            }
        };
    }

    /** Operator locks that run out are released with an event ({@link LockExpiries}). */
    public void expireLocks(ScheduledExecutorService timers, Map<String, OperatorLock> locks,
                     Consumer<String> released) {
        lockExpiries = new LockExpiries(timers, locks, console, released);
    }

    /** An operator took or renewed the lock on a MailBox ({@code ?lock}). */
    public void lockTaken(String mailbox, OperatorLock lock) {
        if (lockExpiries != null) {
            lockExpiries.taken(mailbox, lock);
        }
    }

    /**
     * The permit file changed: watches whose user lost the read right end, each told why once;
     * notifications check the rules in force at each delivery (Notifier).
     */
    public void permitsChanged(PermitFile rules) {
        console.recheck((user, mailbox) -> {
            String why = Rights.whyNotRead(rules, user, mailbox);
            return why == null ? null : why + "; the permit file changed";
        });
    }

    public ConsoleHub console() {
        return console;
    }

    public ConsoleCommands consoleCommands() {
        return consoleCommands;
    }

    public NotifyCommands notifyCommands() {
        return notifyCommands;
    }

    public SurfacingCommands surfacingCommands() {
        return surfacingCommands;
    }

    public Surfacings surfacings() {
        return surfacings;
    }

    /** A client left: its watches go, and its locks are released (an event each). */
    /** @return true when the client held operator locks (now released) */
    public boolean clientClosed(String clientId, Map<String, OperatorLock> locks) {
        console.clientClosed(clientId);
        return locks.entrySet().removeIf(e -> {
            boolean mine = e.getValue().clientId().equals(clientId);
            if (mine && !e.getValue().expired()) {
                console.serverEvent(e.getKey(), VehicleEvent.LOCK_RELEASED, e.getValue().user(), "its holder disconnected");
            }
            return mine;
        });
    }

    @Override
    public void close() {
        if (lockExpiries != null) {
            lockExpiries.close();
        }
        surfacings.close();
        notifier.close();
        console.close();
    }
}
