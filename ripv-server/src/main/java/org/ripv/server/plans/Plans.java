package org.ripv.server.plans;

import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.VehicleEvent;
import org.ripv.plans.PlanLimits;
import org.ripv.plans.SurfacingFacts;
import org.ripv.server.files.FileExistsException;
import org.ripv.server.files.FileTooLargeException;
import org.ripv.surfacing.Surfacing;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The plans part of the server: its commands and its change follower. Console entries reach it
 * through {@link #onConsole} and are handled on one thread of its own ({@code ripv-plans}),
 * behind a bounded queue, so the console is never held up by it.
 */
public final class Plans implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Plans.class);

    private final ChangeBook book;
    private final PlanCommands commands;
    private final ChangeFollower follower;
    private final Fixes fixes = new Fixes();
    private final ThreadPoolExecutor thread;

    public Plans(PlanHost host, Path dir) throws IOException {
        this.book = new ChangeBook(dir);
        this.commands = new PlanCommands(host, book, PlanLimits.DEFAULT, fixes, new PlanVersions(dir.resolve("history")));
        this.follower = new ChangeFollower(book, host.files(), host::publish);
        this.thread = new ThreadPoolExecutor(1, 1, 0, TimeUnit.SECONDS, new ArrayBlockingQueue<>(10_000), r -> {
            Thread t = new Thread(r, "ripv-plans");
            t.setDaemon(true);
            return t;
        }, (r, ex) -> log.warn("plans: the change follower is behind; a batch of console entries was not looked at"));
    }

    /** Console entries of any MailBox (a service's, or the server's own). */
    public void onConsole(List<ConsoleEntry> entries) {
        if (entries.isEmpty() || thread.isShutdown()) {
            return;
        }
        List<ConsoleEntry> copy = List.copyOf(entries);
        thread.execute(() -> {
            for (ConsoleEntry e : copy) {
                if (e.kind() == ConsoleEntry.Kind.EVENT && (e.event() == VehicleEvent.PLAN_CHANGE || e.event() == VehicleEvent.ALERT)) {
                    continue; // ours, or a line's alert: nothing to follow
                }
                try {
                    fixes.take(e);
                    follower.take(e);
                } catch (RuntimeException x) {
                    log.warn("plans: a console entry of {} could not be followed: {}", e.mailbox(), x.toString());
                }
            }
        });
    }

    /**
     * One surface dialog as the surfacing parser read it ({@code org.ripv.server.surfacing.Surfacings}
     * records each): {@code time} is when the dialog began (epoch ms).
     */
    public void surfacing(String mailbox, long time, Surfacing dialog) {
        surfacing(facts(mailbox, time, dialog));
    }

    /** What the follower needs of a parsed dialog: its sensors by lower-case name, the first value of each. */
    static SurfacingFacts facts(String mailbox, long time, Surfacing dialog) {
        Map<String, Double> sensors = new LinkedHashMap<>();
        for (Surfacing.Sensor s : dialog.sensors().values()) {
            if (s.value() != null) {
                sensors.putIfAbsent(s.name().toLowerCase(Locale.ROOT), s.value());
            }
        }
        return SurfacingFacts.of(mailbox, time, sensors);
    }

    /** One surfacing's facts (from {@link #surfacing(String, long, Surfacing)}, or a test). */
    public void surfacing(SurfacingFacts facts) {
        thread.execute(() -> {
            follower.judge(facts); // first: whoever sees the new heading (?plan current) sees the verdict it brought too
            fixes.take(facts);
        });
    }

    /** {@code ?plan ...}. */
    public OutgoingServerMessage planCommand(IncomingServerMessage request) throws IOException {
        return answer(request, Ids.FID_PLAN, () -> commands.plan(request));
    }

    /** {@code ?changes [MAILBOX]}. */
    public OutgoingServerMessage changesCommand(IncomingServerMessage request) throws IOException {
        // a staged file deleted or replaced since the last call shows as cancelled at once, not only on the next call
        try {
            thread.submit(() -> follower.sweep(null)).get(2, TimeUnit.SECONDS);
        } catch (ExecutionException | TimeoutException
                 | RejectedExecutionException e) {
            log.debug("plans: the sweep of staged files did not finish: {}", e.toString());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return answer(request, Ids.FID_CHANGES, () -> commands.changes(request));
    }

    private interface Command {
        OutgoingServerMessage run() throws IOException;
    }

    private static OutgoingServerMessage answer(IncomingServerMessage request, String fid, Command c) throws IOException {
        try {
            return c.run();
        } catch (PlanCommands.Refused e) {
            return PlanCommands.error(request, fid, ErrorCode.FORBIDDEN, e.getMessage());
        } catch (FileExistsException e) {
            return PlanCommands.error(request, fid, ErrorCode.FILE_EXISTS, e.getMessage());
        } catch (FileTooLargeException e) {
            return PlanCommands.error(request, fid, ErrorCode.TOO_LARGE, e.getMessage());
        } catch (NoSuchFileException e) {
            return PlanCommands.error(request, fid, ErrorCode.BAD_FILE_NAME, e.getMessage());
        } catch (IllegalArgumentException e) {
            return PlanCommands.error(request, fid, ErrorCode.BAD_REQUEST, e.getMessage());
        }
    }

    @Override
    public void close() {
        thread.shutdown();
        try {
            thread.awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
