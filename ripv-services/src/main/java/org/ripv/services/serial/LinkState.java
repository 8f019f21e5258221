package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import org.ripv.messages.VehicleEvent;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Which connection a vehicle link has now, and how it comes and goes: outbound links (devices,
 * {@code tcp://}) are opened on demand and reopened by a monitor task; on a {@code listen://} link
 * the {@link CallListener} hands in callers, one call at a time. Every connection's end is
 * reported to the {@link VehicleConsole} as the call's end (DIVED or LINK_LOST), once.
 *
 * <p>The current connection changes under this object's monitor; the command lock is the
 * {@link SerialPortHandler}'s, which the monitor task only ever {@code tryLock}s.
 */
final class LinkState {
    private static final Logger log = LoggerFactory.getLogger(LinkState.class);

    private final String handle;
    private final VehicleLink vehicle;
    private final LinkSettings settings;
    private final VehicleConsole console;
    private final SerialPortHandler.LinkOpener opener;
    private final ReentrantLock commandLock;
    private final Connection.Traffic traffic = new Traffic();
    private volatile Connection link;
    private volatile String downReason = "not opened yet";
    private volatile boolean closed;
    private volatile ScheduledFuture<?> monitor;
    private volatile CallListener calls;

    LinkState(VehicleLink vehicle, VehicleConsole console, SerialPortHandler.LinkOpener opener,
              ReentrantLock commandLock) {
        this.handle = vehicle.handle();
        this.vehicle = vehicle;
        this.settings = vehicle.settings();
        this.console = console;
        this.opener = opener;
        this.commandLock = commandLock;
    }

    /**
     * Starts taking calls (listen links), or tries to open the link now and keeps retrying on
     * {@code scheduler}.
     *
     * @throws IOException when a listen link's address cannot be bound
     */
    void start(ScheduledExecutorService scheduler) throws IOException {
        if (vehicle.isListen()) {
            calls = CallListener.open(VehicleLink.listenUri(settings.device()), handle, vehicle.call().callers(),
                    this::incoming);
            downReason = "no call yet";
            return;
        }
        if (settings.carrier() == CarrierMode.REQUIRE && settings.isTcp()) {
            log.warn("{}: --carrier require has no effect on {}: TCP has no DCD line", handle, settings.device());
        }
        scheduler.execute(this::monitor);
        long every = settings.reconnectEvery().toMillis();
        monitor = scheduler.scheduleWithFixedDelay(this::monitor, every, every, TimeUnit.MILLISECONDS);
    }

    /** The open connection, or null. */
    Connection current() {
        return link;
    }

    String downReason() {
        return downReason;
    }

    /** {@code listen://127.0.0.1:2323} for a listen link. */
    String listening() {
        return calls == null ? "" : calls.describe();
    }

    int listenPort() {
        CallListener c = calls;
        return c == null ? -1 : c.port();
    }

    /** Opens an outbound link (device or tcp://) and starts its reader. Call with the command lock held. */
    void tryOpen() {
        if (vehicle.isListen()) {
            return;
        }
        try {
            Link opened = opener.open(settings);
            Connection c = new Connection(opened, traffic, handle, false).start();
            try {
                settle(c);
            } catch (IOException e) {
                c.close();
                throw e;
            }
            synchronized (this) {
                if (closed) {
                    c.close();
                    return;
                }
                link = c;
                downReason = "";
            }
            log.info("{}: link {} is up", handle, opened.describe());
        } catch (IOException | RuntimeException e) {
            String why = e.getMessage() == null ? e.toString() : e.getMessage();
            if (!why.equals(downReason)) {
                log.warn("{}: cannot open {}: {}", handle, settings.device(), why);
            }
            downReason = why;
        }
    }


    /** Lets a fresh connection's banner pass (to the console), so it is not taken for the first reply. */
    private void settle(Connection c) throws IOException {
        byte[] buf = new byte[4096];
        long deadline = System.nanoTime() + settings.idleTimeout().toNanos();
        c.listen();
        try {
            while (System.nanoTime() - deadline < 0 && c.read(buf, 0, buf.length, 100) > 0) {
                log.debug("{}: a greeting passed", handle);
            }
        } finally {
            c.stopListening();
        }
    }

    /** A vehicle called in on a listen link: it becomes the link, unless a call is on already. */
    private void incoming(Socket socket) {
        Connection c;
        synchronized (this) {
            if (!closed && link == null) {
                try {
                    c = new Connection(new TcpLink(socket), traffic, handle, true);
                } catch (IOException e) {
                    log.warn("{}: a call from {} failed at once: {}", handle, socket.getRemoteSocketAddress(), e.toString());
                    closeQuietly(socket);
                    return;
                }
                link = c;
                downReason = "";
                console.callStarted("caller " + c.describe().substring("tcp://".length()));
                c.start();
                log.info("{}: call from {}", handle, c.describe());
                return;
            }
        }
        refuse(socket);
    }

    /** One line to a second caller, then hang up; it is never mixed into the call. */
    private void refuse(Socket socket) {
        log.info("{}: refused a call from {}: a call is on", handle, socket.getRemoteSocketAddress());
        try (socket) {
            socket.setSoTimeout(1_000);
            socket.getOutputStream().write(("RIPV: " + handle + " is on a call already; try again later\r\n")
                    .getBytes(StandardCharsets.US_ASCII));
            socket.getOutputStream().flush();
        } catch (IOException e) {
            log.debug("{}: refusing {}: {}", handle, socket.getRemoteSocketAddress(), e.toString());
        }
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // it is going anyway
        }
    }

    /** The link ended: a caller hung up (DIVED) or the link failed (LINK_LOST). Idempotent. */
    void failed(Connection l, IOException e) {
        synchronized (this) {
            if (link != l) {
                return;
            }
            link = null;
            downReason = e.getMessage() == null ? e.toString() : e.getMessage();
        }
        l.close();
        if (l.isCall()) {
            boolean hungUp = e instanceof EOFException;
            // A caller that hangs up while a command or transfer runs, or in the middle of its surface
            // dialog, dropped the call (a satellite link failing); only one that hangs up after its
            // dialog, between commands, dived.
            String dropped = hungUp ? console.droppedMidway(commandLock.isLocked()) : null;
            log.info("{}: call from {} ended: {}{}", handle, l.describe(), downReason, dropped == null ? "" : " (" + dropped + ")");
            console.callEnded(hungUp && dropped == null ? VehicleEvent.DIVED : VehicleEvent.LINK_LOST,
                    !hungUp ? "the call failed: " + downReason : dropped == null ? "the caller hung up" : dropped);
        } else {
            log.warn("{}: link {} failed: {}", handle, l.describe(), downReason);
            console.callEnded(VehicleEvent.LINK_LOST, "link " + l.describe() + " failed: " + downReason);
        }
    }

    /** Ends a call from this side. */
    private void hangUp(Connection l, String why) {
        synchronized (this) {
            if (link != l) {
                return;
            }
            link = null;
            downReason = why;
        }
        log.info("{}: call from {}: {}", handle, l.describe(), why);
        l.close();
        console.callEnded(VehicleEvent.DIVED, why);
    }

    /** Reopens a down outbound link. */
    private void monitor() {
        if (!commandLock.tryLock()) {
            return; // a command is using the link
        }
        try {
            if (link == null && !closed) {
                tryOpen();
            }
        } catch (RuntimeException e) {
            log.warn("{}: link monitor: {}", handle, e.toString());
        } finally {
            commandLock.unlock();
        }
    }

    /** What the reader sees, on the reader's thread. */
    private final class Traffic implements Connection.Traffic {
        private boolean carrier;

        @Override
        public void text(byte[] bytes, int length) {
            console.text(bytes, 0, length);
        }

        @Override
        public void alive() {
            console.alive();
        }

        @Override
        public void tick(Connection c) {
            console.tick();
            if (c.isCall() && console.quietTooLong() && !commandLock.isLocked()) {
                // a caller that says nothing (a stuck gateway, or someone holding the line) would
                // keep the vehicle itself from calling in
                hangUp(c, "quiet for " + console.quietSeconds() + " s: hung up");
                return;
            }
            if (console.calls() == VehicleConsole.Calls.CARRIER && c.hasCarrierLine()) {
                boolean now = c.carrier();
                if (now != carrier) {
                    carrier = now;
                    if (now) {
                        console.callStarted("carrier rose on " + c.describe());
                    } else {
                        console.callEnded(VehicleEvent.DIVED, "carrier fell");
                    }
                }
            }
        }

        @Override
        public void ended(Connection c, IOException e) {
            carrier = false;
            failed(c, e);
        }
    }

    void close() {
        if (monitor != null) {
            monitor.cancel(false);
        }
        if (calls != null) {
            calls.close();
        }
        Connection l;
        synchronized (this) {
            closed = true;
            l = link;
            link = null;
            downReason = "closed";
        }
        if (l != null) {
            l.close();
        }
    }
}
