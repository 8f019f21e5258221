package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.VehicleEvent;
import org.ripv.service.Availability;
import org.ripv.service.CommandHandler;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.ripv.services.serial.ymodem.YmodemException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Owns one link to a vehicle and runs its MailBox's commands (thesis: SerialPortHandler).
 *
 * <ul>
 *   <li>A plain command is written with the line ending; the reply is read until the prompt or
 *       the idle timeout, and returned without the echoed command line and the prompt.</li>
 *   <li>{@code ymodem:get NAME…} and {@code ymodem:put NAME}: {@link YmodemCommands}.</li>
 * </ul>
 *
 * <p>The link is read all the time by its {@link Connection}'s reader, which feeds the
 * {@link VehicleConsole} (the live console and the call's events) and, while a command runs, the
 * command. Outbound links (devices, {@code tcp://}) are opened here and reopened by a monitor
 * task; on a {@code listen://} link the {@link CallListener} hands in callers, one call at a time.
 *
 * <p>Threading: commands arrive one at a time from the MailBox's inbox assistant and hold
 * {@link #lock} while they use the link; the monitor only ever {@code tryLock}s, so it never
 * delays a command. Which connection is current changes under this object's monitor.
 */
public final class SerialPortHandler implements CommandHandler, AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(SerialPortHandler.class);

    /** Opens a link; {@link Links#open} in production. */
    @FunctionalInterface
    public interface LinkOpener {
        Link open(LinkSettings settings) throws IOException;
    }

    private final String handle;
    private final VehicleLink vehicle;
    private final LinkSettings settings;
    private final VehicleText vehicleText;
    private final ReplyReader replies;
    private final VehicleConsole console;
    private final YmodemCommands ymodem;
    private final LinkOpener opener;
    private final ReentrantLock lock = new ReentrantLock();
    private final Connection.Traffic traffic = new Traffic();
    private volatile Connection link;
    private volatile String downReason = "not opened yet";
    private volatile boolean closed;
    private ScheduledFuture<?> monitor;
    private CallListener calls;

    /**
     * @param handle   the MailBox handle, for messages
     * @param settings how to open and talk to the link
     * @param workDir  where incoming YMODEM files are assembled before they are returned
     */
    public SerialPortHandler(String handle, LinkSettings settings, Path workDir, LinkOpener opener) {
        this(VehicleLink.of(settings), handle, workDir, opener, entry -> { });
    }

    /**
     * @param mailbox  the MailBox address console entries carry
     * @param publish  where console entries go ({@code RIPVService.publish})
     */
    SerialPortHandler(VehicleLink vehicle, String mailbox, Path workDir, LinkOpener opener,
                      Consumer<ConsoleEntry> publish) {
        this.handle = vehicle.handle();
        this.vehicle = vehicle;
        this.settings = vehicle.settings();
        this.vehicleText = new VehicleText(settings.prompt());
        this.replies = new ReplyReader(settings, vehicleText);
        VehicleConsole.Calls how = vehicle.isListen() ? VehicleConsole.Calls.CALLER
                : settings.carrier() == CarrierMode.REQUIRE && !settings.isTcp() ? VehicleConsole.Calls.CARRIER
                : VehicleConsole.Calls.DIALOG;
        this.console = new VehicleConsole(mailbox, vehicle.call(), settings.prompt(), how, publish);
        this.ymodem = new YmodemCommands(handle, settings, vehicleText, console, workDir);
        this.opener = opener;
    }

    /**
     * Starts taking calls (listen links), or tries to open the link now and keeps retrying (and
     * checking it) on {@code scheduler}.
     *
     * @throws IOException when a listen link's address cannot be bound
     */
    public void start(ScheduledExecutorService scheduler) throws IOException {
        if (vehicle.isListen()) {
            calls = CallListener.open(VehicleLink.listenUri(settings.device()), handle, this::incoming);
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

    public LinkSettings settings() {
        return settings;
    }

    /** The port a listen link is bound to (useful with port 0), or -1. */
    public int listenPort() {
        CallListener c = calls;
        return c == null ? -1 : c.port();
    }

    @Override
    public Availability availability() {
        Connection l = link;
        String call = console.state() == CallState.State.NEVER && !vehicle.isListen() ? "" : "; " + console.describe();
        if (l == null) {
            if (vehicle.isListen()) {
                return Availability.notAvailable("not on a call (" + console.describe() + "); waiting for calls on "
                        + calls.describe());
            }
            return Availability.notAvailable("link " + settings.device() + " is down (" + downReason
                    + "); retrying every " + settings.reconnectEvery().toSeconds() + " s" + call);
        }
        if (settings.carrier() == CarrierMode.REQUIRE && !l.carrier()) {
            return Availability.notAvailable("no carrier (DCD low) on " + l.describe() + call);
        }
        return Availability.available(l.describe() + call);
    }

    @Override
    public Reply execute(Request request) throws Exception {
        lock.lockInterruptibly();
        try {
            Connection l = usableLink();
            String command = request.command().trim();
            console.command(request.user(), command);
            try {
                if (command.startsWith("ymodem:get")) {
                    return ymodem.get(l, request);
                }
                if (command.startsWith("ymodem:put")) {
                    return ymodem.put(l, request);
                }
                if (command.startsWith("ymodem:")) {
                    throw new ServiceException(ErrorCode.UNKNOWN_COMMAND,
                            "unknown '" + command.split("\\s+")[0] + "'; use ymodem:get NAME… or ymodem:put NAME");
                }
                return plain(l, command);
            } catch (EOFException e) {
                linkFailed(l, e);
                throw new ServiceException(ErrorCode.DEVICE_ERROR, e.getMessage()
                        + "; the link will be reopened when it comes back");
            } catch (YmodemException e) {
                throw new ServiceException(ErrorCode.TRANSFER_FAILED, "YMODEM transfer failed: " + e.getMessage());
            } catch (IOException e) {
                linkFailed(l, e);
                throw new ServiceException(ErrorCode.DEVICE_ERROR, "link " + l.describe() + " failed: " + e
                        + "; the link will be reopened when it comes back");
            }
        } finally {
            lock.unlock();
        }
    }

    private Connection usableLink() throws ServiceException {
        if (link == null && !vehicle.isListen()) {
            tryOpen();
        }
        Connection l = link;
        if (l == null) {
            if (vehicle.isListen()) {
                throw new ServiceException(ErrorCode.NOT_AVAILABLE, handle + " is not on a call (" + console.describe()
                        + "); commands can be sent while it is, after it calls in on " + calls.describe());
            }
            throw new ServiceException(ErrorCode.NOT_AVAILABLE, "link " + settings.device() + " is not available: "
                    + downReason);
        }
        if (settings.carrier() == CarrierMode.REQUIRE && !l.carrier()) {
            throw new ServiceException(ErrorCode.NOT_AVAILABLE, "no carrier (DCD low) on " + l.describe()
                    + "; nothing was sent");
        }
        return l;
    }

    // ---- plain commands

    private Reply plain(Connection l, String command) throws IOException, ServiceException {
        StringBuilder text = new StringBuilder();
        boolean closed;
        l.listen();
        try {
            l.write((command + settings.lineEnding()).getBytes(StandardCharsets.ISO_8859_1));
            l.flush();
            closed = replies.read(l, text, settings.commandTimeout().toMillis(), command);
        } finally {
            l.stopListening();
        }
        if (text.isEmpty() && !closed) {
            throw new ServiceException(ErrorCode.TIMEOUT, "no answer to '" + command + "' from " + l.describe()
                    + " within " + settings.idleTimeout().toMillis() + " ms");
        }
        String reply = vehicleText.clean(text.toString(), command);
        if (closed) {
            linkFailed(l, new EOFException("closed by the vehicle"));
            return Reply.ok(reply + (reply.isEmpty() ? "" : "\n") + "(the vehicle closed the link)");
        }
        return Reply.ok(reply);
    }

    // ---- link state

    /** Opens an outbound link (device or tcp://) and starts its reader. */
    private void tryOpen() {
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
    private void linkFailed(Connection l, IOException e) {
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
            log.info("{}: call from {} ended: {}", handle, l.describe(), downReason);
            console.callEnded(hungUp ? VehicleEvent.DIVED : VehicleEvent.LINK_LOST,
                    hungUp ? "the caller hung up" : "the call failed: " + downReason);
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
        if (!lock.tryLock()) {
            return; // a command is using the link
        }
        try {
            if (link == null && !closed) {
                tryOpen();
            }
        } catch (RuntimeException e) {
            log.warn("{}: link monitor: {}", handle, e.toString());
        } finally {
            lock.unlock();
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
            if (c.isCall() && console.quietTooLong() && !lock.isLocked()) {
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
            linkFailed(c, e);
        }
    }

    @Override
    public void close() {
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
