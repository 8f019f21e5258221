package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import org.ripv.commands.SingleLineCommand;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.service.Availability;
import org.ripv.service.CommandHandler;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.ripv.services.serial.ymodem.YmodemException;

/**
 * Owns one link to a vehicle and runs its MailBox's commands (thesis: SerialPortHandler). A
 * command's first word is looked up in the link's table ({@link LinkCommands}):
 *
 * <ul>
 *   <li>A plain command: {@link PlainCommands}.</li>
 *   <li>{@code ymodem:get NAME…} and {@code ymodem:put NAME}: {@link YmodemCommands}.</li>
 *   <li>{@code zmodem:get NAME…} and {@code zmodem:put NAME}: {@link ZmodemCommands}.</li>
 *   <li>{@code tovehicle:put to-vehicle/FOLDER/NAME}, a file of the server's to-vehicle folder: {@link ToVehicleCommands}.</li>
 *   <li>{@code ?key KEY}, one control key (the server's {@code ?key MAILBOX KEY}): {@link KeyCommands}.</li>
 * </ul>
 *
 * <p>The link is read all the time by its {@link Connection}'s reader, which feeds the
 * {@link VehicleConsole} (the live console and the call's events) and, while a command runs, the
 * command. Which connection is current, and how links and calls come and go: {@link LinkState}.
 *
 * <p>Threading: commands arrive one at a time from the MailBox's inbox assistant and hold
 * {@link #lock} while they use the link; the link monitor only ever {@code tryLock}s it, so it
 * never delays a command.
 */
public final class SerialPortHandler implements CommandHandler, AutoCloseable {

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
    private final ZmodemCommands zmodem;
    private final KeyCommands keys;
    private final ReentrantLock lock = new ReentrantLock();
    private final LinkState state;
    private final PlainCommands plain;
    private final LinkCommands commands;
    private final RunningCommand running = new RunningCommand();

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
        this.ymodem = new YmodemCommands(handle, settings, vehicleText, console, workDir, running);
        this.zmodem = new ZmodemCommands(handle, settings, vehicle.pilot(), vehicleText, console, workDir, running);
        this.keys = new KeyCommands(handle, vehicle.pilot(), settings, replies);
        this.state = new LinkState(vehicle, console, opener, lock);
        this.plain = new PlainCommands(settings, vehicleText, replies, console, state);
        this.commands = new LinkCommands(ymodem, zmodem, new ToVehicleCommands(vehicle.pilot(), zmodem, ymodem, plain), keys);
    }

    /**
     * Starts taking calls (listen links), or tries to open the link now and keeps retrying (and
     * checking it) on {@code scheduler}.
     *
     * @throws IOException when a listen link's address cannot be bound
     */
    public void start(ScheduledExecutorService scheduler) throws IOException {
        ymodem.prepareWorkDir();
        state.start(scheduler);
    }

    public LinkSettings settings() {
        return settings;
    }

    /** The port a listen link is bound to (useful with port 0), or -1. */
    public int listenPort() {
        return state.listenPort();
    }

    @Override
    public Availability availability() {
        Connection l = state.current();
        // The keys ?key may press here, for the clients' key bars (the web console's vehicle page reads "keys: ...").
        String keys = "; keys: " + ControlKey.describe(vehicle.pilot().keys());
        String call = (console.state() == CallState.State.NEVER && !vehicle.isListen() ? "" : "; " + console.describe()) + keys;
        if (l == null) {
            if (vehicle.isListen()) {
                return Availability.notAvailable("not on a call (" + console.describe() + "); waiting for calls on "
                        + state.listening() + keys);
            }
            return Availability.notAvailable("link " + settings.device() + " is down (" + state.downReason()
                    + "); retrying every " + settings.reconnectEvery().toSeconds() + " s" + call);
        }
        if (settings.carrier() == CarrierMode.REQUIRE && !l.carrier()) {
            return Availability.notAvailable("no carrier (DCD low) on " + l.describe() + call);
        }
        String now = running.describe();
        return now == null ? Availability.available(l.describe() + call)
                : Availability.running(now, l.describe() + call);
    }

    /**
     * Cancels a running YMODEM transfer ({@link YmodemCommands#cancel}: CAN CAN, then back to the
     * prompt) or plain command ({@link CommandCancel}: the link's interrupt, then its prompt).
     * False for a link whose interrupt is {@code none}.
     */
    @Override
    public boolean cancel(Request running) {
        return ymodem.cancel() || zmodem.cancel() || plain.cancel();
    }

    @Override
    public Reply execute(Request request) throws Exception {
        // Defence in depth: the server refuses these already, but nothing but one line ever reaches the link.
        try {
            SingleLineCommand.check(request.command(), settings.maxCommand());
        } catch (IllegalArgumentException e) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, e.getMessage() + " (link " + handle + ")");
        }
        String command = request.command().trim();
        // a link command's own checks (a key the link allows, to-vehicle files on) come before the lock
        LinkCommands.Command linkCommand = commands.find(command).orElse(null);
        String shown = linkCommand == null ? null : linkCommand.before().check(request);
        lock.lockInterruptibly();
        try {
            Connection l = usableLink();
            console.command(request.user(), shown != null ? shown : command);
            running.start(command, request.user());
            try {
                return linkCommand != null ? linkCommand.run().run(l, request) : plain.run(l, command, request.user());
            } catch (EOFException e) {
                state.failed(l, e);
                throw new ServiceException(ErrorCode.DEVICE_ERROR, e.getMessage()
                        + "; the link will be reopened when it comes back");
            } catch (YmodemException e) {
                throw new ServiceException(ErrorCode.TRANSFER_FAILED, "YMODEM transfer failed: " + e.getMessage());
            } catch (IOException e) {
                state.failed(l, e);
                throw new ServiceException(ErrorCode.DEVICE_ERROR, "link " + l.describe() + " failed: " + e
                        + "; the link will be reopened when it comes back");
            } finally {
                running.end();
            }
        } finally {
            lock.unlock();
        }
    }

    private Connection usableLink() throws ServiceException {
        if (state.current() == null) {
            state.tryOpen();
        }
        Connection l = state.current();
        if (l == null) {
            if (vehicle.isListen()) {
                throw new ServiceException(ErrorCode.NOT_AVAILABLE, handle + " is not on a call (" + console.describe()
                        + "); commands can be sent while it is, after it calls in on " + state.listening());
            }
            throw new ServiceException(ErrorCode.NOT_AVAILABLE, "link " + settings.device() + " is not available: "
                    + state.downReason());
        }
        if (settings.carrier() == CarrierMode.REQUIRE && !l.carrier()) {
            throw new ServiceException(ErrorCode.NOT_AVAILABLE, "no carrier (DCD low) on " + l.describe()
                    + "; nothing was sent");
        }
        return l;
    }

    @Override
    public void close() {
        state.close();
    }
}
