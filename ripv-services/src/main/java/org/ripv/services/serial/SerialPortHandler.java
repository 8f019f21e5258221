package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.ReentrantLock;
import java.util.stream.Stream;
import org.ripv.commands.SingleLineCommand;
import org.ripv.exceptions.ServiceException;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.Header;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileBundle;
import org.ripv.messages.FileData;
import org.ripv.service.Availability;
import org.ripv.service.CommandHandler;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.ripv.services.serial.ymodem.AskedNames;
import org.ripv.services.serial.ymodem.DirectorySink;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.FileNames;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.YmodemException;
import org.ripv.services.serial.ymodem.YmodemReceiver;
import org.ripv.services.serial.ymodem.YmodemSender;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Owns one link to a vehicle and runs its MailBox's commands (thesis: SerialPortHandler).
 *
 * <ul>
 *   <li>A plain command is written with the line ending; the reply is read until the prompt or
 *       the idle timeout, and returned without the echoed command line and the prompt.</li>
 *   <li>{@code ymodem:get NAME…} writes the vehicle's send command and receives the batch;
 *       the reply carries the files (the server stores them in its download directory).</li>
 *   <li>{@code ymodem:put NAME} writes the vehicle's receive command and sends the file the
 *       server attached from its upload directory.</li>
 * </ul>
 *
 * <p>Threading: commands arrive one at a time from the MailBox's inbox assistant; a monitor
 * task on the shared scheduler reopens a link that is down and checks an idle one for a
 * vanished peer. Both hold {@link #lock} while touching the link; the monitor only ever
 * {@code tryLock}s, so it never delays a command.
 */
public final class SerialPortHandler implements CommandHandler, AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(SerialPortHandler.class);
    private static final AtomicLong TRANSFERS = new AtomicLong();

    /** Opens a link; {@link Links#open} in production. */
    @FunctionalInterface
    public interface LinkOpener {
        Link open(LinkSettings settings) throws IOException;
    }

    private final String handle;
    private final LinkSettings settings;
    private final VehicleText vehicleText;
    private final Path workDir;
    private final LinkOpener opener;
    private final ReentrantLock lock = new ReentrantLock();
    private volatile Link link;
    private volatile String downReason = "not opened yet";
    private ScheduledFuture<?> monitor;
    /** A YMODEM transfer is under way, and whether ?cancel asked it to stop (checked before every block). */
    private volatile boolean transferring;
    private volatile boolean cancelRequested;

    /**
     * @param handle   the MailBox handle, for messages
     * @param settings how to open and talk to the link
     * @param workDir  where incoming YMODEM files are assembled before they are returned
     */
    public SerialPortHandler(String handle, LinkSettings settings, Path workDir, LinkOpener opener) {
        this.handle = handle;
        this.settings = settings;
        this.vehicleText = new VehicleText(settings.prompt());
        this.workDir = workDir;
        this.opener = opener;
    }

    /** Tries to open the link now and keeps retrying (and checking it) on {@code scheduler}. */
    public void start(ScheduledExecutorService scheduler) {
        if (settings.carrier() == CarrierMode.REQUIRE && settings.isTcp()) {
            log.warn("{}: --carrier require has no effect on {}: TCP has no DCD line", handle, settings.device());
        }
        DirectorySink.prepareWorkDir(workDir); // owner-only; partial files of an earlier run that was killed go
        scheduler.execute(this::monitor);
        long every = settings.reconnectEvery().toMillis();
        monitor = scheduler.scheduleWithFixedDelay(this::monitor, every, every, TimeUnit.MILLISECONDS);
    }

    public LinkSettings settings() {
        return settings;
    }

    @Override
    public Availability availability() {
        Link l = link;
        if (l == null) {
            return Availability.notAvailable("link " + settings.device() + " is down (" + downReason
                    + "); retrying every " + settings.reconnectEvery().toSeconds() + " s");
        }
        if (settings.carrier() == CarrierMode.REQUIRE && !l.carrier()) {
            return Availability.notAvailable("no carrier (DCD low) on " + l.describe());
        }
        return Availability.available(l.describe());
    }

    /**
     * Cancels a running YMODEM transfer: it aborts with CAN CAN before its next block and the
     * line is brought back to the prompt as after any failed transfer. A plain command is not
     * cancelled yet (the link's interrupt belongs to the link's reader).
     */
    @Override
    public boolean cancel(Request running) {
        if (!transferring) {
            return false;
        }
        cancelRequested = true;
        return true;
    }

    @Override
    public Reply execute(Request request) throws Exception {
        // Defence in depth: the server refuses these already, but nothing but one line ever reaches the link.
        try {
            SingleLineCommand.check(request.command(), settings.maxCommand());
        } catch (IllegalArgumentException e) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, e.getMessage() + " (link " + handle + ")");
        }
        lock.lockInterruptibly();
        cancelRequested = false;
        try {
            Link l = usableLink();
            String command = request.command().trim();
            try {
                if (command.startsWith("ymodem:get")) {
                    return get(l, request);
                }
                if (command.startsWith("ymodem:put")) {
                    return put(l, request);
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
                resync(l);
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

    private Link usableLink() throws ServiceException {
        if (link == null) {
            tryOpen();
        }
        Link l = link;
        if (l == null) {
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

    private Reply plain(Link l, String command) throws IOException, ServiceException {
        discardInput(l);
        l.write((command + settings.lineEnding()).getBytes(StandardCharsets.ISO_8859_1));
        l.flush();
        StringBuilder text = new StringBuilder();
        boolean closed = readReply(l, text, settings.commandTimeout().toMillis(), command);
        if (text.isEmpty() && !closed) {
            throw new ServiceException(ErrorCode.TIMEOUT, "no answer to '" + Header.abbreviate(command) + "' from " + l.describe()
                    + " within " + settings.idleTimeout().toMillis() + " ms");
        }
        String reply = vehicleText.clean(text.toString(), command);
        if (closed) {
            linkFailed(l, new EOFException("closed by the vehicle"));
            return Reply.ok(reply + (reply.isEmpty() ? "" : "\n") + "(the vehicle closed the link)");
        }
        return Reply.ok(reply);
    }

    /**
     * Reads into {@code text} until the prompt ends it, the line is idle, or {@code maxMillis}
     * pass. Returns true when the link closed meanwhile. A prompt before the echo of
     * {@code command} (a fresh connection's banner) only ends the reply if nothing follows it.
     */
    private boolean readReply(Link l, StringBuilder text, long maxMillis, String command) throws IOException {
        byte[] buf = new byte[4096];
        long deadline = System.nanoTime() + maxMillis * 1_000_000;
        long idle = settings.idleTimeout().toMillis();
        long wait = idle;
        while (System.nanoTime() - deadline < 0) {
            int n;
            try {
                n = l.read(buf, 0, buf.length, wait);
            } catch (EOFException e) {
                return true;
            }
            if (n == 0) {
                return false;
            }
            text.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
            if (vehicleText.endsWithPrompt(text)) {
                if (command == null || VehicleText.echoEnd(text, command) >= 0) {
                    return false;
                }
                wait = Math.min(idle, 200); // a banner's prompt, or a vehicle that does not echo
            } else {
                wait = idle;
            }
        }
        return false;
    }

    private boolean readReply(Link l, StringBuilder text, long maxMillis) throws IOException {
        return readReply(l, text, maxMillis, null);
    }

    /** Throws away whatever the vehicle said unasked, so it does not end up in the next reply. */
    private static void discardInput(Link l) throws IOException {
        byte[] buf = new byte[4096];
        int n;
        int total = 0;
        while ((n = l.read(buf, 0, buf.length, 1)) > 0 && total < 1 << 20) {
            total += n;
        }
        if (total > 0) {
            log.debug("discarded {} unsolicited bytes from {}", total, l.describe());
        }
    }

    /** Writes a vehicle command on a line cleared of earlier chatter. */
    private void startVehicleCommand(Link l, String vehicleCommand) throws IOException {
        discardInput(l);
        l.write((vehicleCommand + settings.lineEnding()).getBytes(StandardCharsets.ISO_8859_1));
        l.flush();
    }

    /** After a failed transfer, lets the vehicle finish and return to its prompt. */
    private void resync(Link l) {
        try {
            StringBuilder ignored = new StringBuilder();
            readReply(l, ignored, settings.idleTimeout().toMillis() * 2);
        } catch (IOException e) {
            linkFailed(l, e);
        }
    }

    // ---- YMODEM

    private Reply get(Link l, Request request) throws IOException, ServiceException {
        List<String> names = request.arguments();
        if (names.isEmpty()) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, "ymodem:get needs file names, e.g. ymodem:get MISSION1.LOG");
        }
        for (String name : names) {
            try {
                FileNames.requirePlain(name);
            } catch (IllegalArgumentException e) {
                throw new ServiceException(ErrorCode.BAD_FILE_NAME, e.getMessage());
            }
        }
        Path dir = PrivateFiles.createDirectories(workDir).resolve("get-" + TRANSFERS.incrementAndGet());
        try {
            DirectorySink sink = new DirectorySink(dir);
            String vehicleCommand = settings.sendCommand() + " " + String.join(" ", names);
            startVehicleCommand(l, vehicleCommand);
            ProgressReporter progress = new ProgressReporter(request, "receiving");
            List<FileHeader> files;
            transferring = true;
            try {
                files = new YmodemReceiver(l, settings.ymodem(), progress).cancelWhen(() -> cancelRequested)
                        .stopWaitingWhen(text -> vehicleText.promptAfterEcho(text, vehicleCommand)).receiveBatch(sink);
            } catch (YmodemException e) {
                // our 'C's may sit in the shell's line: end that line so the shell is clean again
                l.write(settings.lineEnding().getBytes(StandardCharsets.ISO_8859_1));
                l.flush();
                throw e;
            } finally {
                transferring = false;
            }
            StringBuilder ignored = new StringBuilder();
            readReply(l, ignored, settings.idleTimeout().toMillis() * 2);
            if (files.isEmpty()) {
                throw new ServiceException(ErrorCode.TRANSFER_FAILED, "the vehicle sent no files for '"
                        + String.join(" ", names) + "'");
            }
            // The vehicle does not choose stored names: block 0 must name a file that was asked for.
            AskedNames.Verdict verdict = new AskedNames(names).check(files);
            verdict.warnings().forEach(w -> log.warn("{}: {}", handle, w));
            String warnings = verdict.warnings().isEmpty() ? "" : "\nwarning: " + String.join("\nwarning: ", verdict.warnings());
            if (verdict.accepted().isEmpty()) {
                throw new ServiceException(ErrorCode.TRANSFER_FAILED, "the vehicle sent none of '"
                        + String.join(" ", names) + "'" + warnings);
            }
            List<FileData> data = new ArrayList<>();
            long bytes = 0;
            for (AskedNames.Accepted a : verdict.accepted()) {
                byte[] content = Files.readAllBytes(dir.resolve(a.file().name()));
                bytes += content.length;
                data.add(FileData.whole(a.storedName(), content));
            }
            String text = "received " + describe(data) + " in " + progress.summary(bytes) + warnings;
            log.info("{}: {}", handle, text);
            return Reply.ok(text, data.size() == 1 ? data.get(0) : new FileBundle(data));
        } finally {
            deleteTree(dir);
        }
    }

    private Reply put(Link l, Request request) throws IOException, ServiceException {
        List<String> args = request.arguments();
        if (args.size() != 1) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, "ymodem:put takes one file name from the server's upload"
                    + " directory, e.g. ymodem:put glider.bin; got " + args.size());
        }
        var attachment = request.attachment().orElseThrow(() -> new ServiceException(ErrorCode.BAD_REQUEST,
                "no file '" + args.get(0) + "' came with ymodem:put; upload it to the server first (put FILE)"));
        SendFile file;
        try {
            file = SendFile.of(FileNames.requirePlain(args.get(0)), attachment.data());
        } catch (IllegalArgumentException e) {
            throw new ServiceException(ErrorCode.BAD_FILE_NAME, e.getMessage());
        }
        startVehicleCommand(l, settings.receiveCommand());
        awaitReceiver(l, settings.receiveCommand());
        ProgressReporter progress = new ProgressReporter(request, "sending");
        transferring = true;
        try {
            new YmodemSender(l, settings.ymodem(), progress).cancelWhen(() -> cancelRequested).sendBatch(List.of(file), true);
        } finally {
            transferring = false;
        }
        StringBuilder after = new StringBuilder();
        readReply(l, after, settings.idleTimeout().toMillis() * 2);
        String text = "sent " + file.name() + " (" + file.length() + " bytes) in " + progress.summary(file.length());
        log.info("{}: {}", handle, text);
        return Reply.ok(text);
    }

    /**
     * Reads past the echo of the vehicle's receive command until its YMODEM receiver asks with a
     * lone 'C'. A shell that answers with text instead ("Bad command", then its prompt, which
     * holds a 'C' too) fails the command with that text rather than getting block 0 typed at it.
     */
    private void awaitReceiver(Link l, String vehicleCommand) throws IOException, ServiceException {
        StringBuilder said = new StringBuilder();
        byte[] buf = new byte[512];
        long deadline = System.nanoTime() + settings.ymodem().startTimeout().toNanos();
        while (System.nanoTime() - deadline < 0) {
            int n = l.read(buf, 0, buf.length, settings.idleTimeout().toMillis());
            if (n > 0) {
                said.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
            }
            int echo = VehicleText.echoEnd(said, vehicleCommand);
            String rest = echo >= 0 ? said.substring(echo) : said.toString();
            if (rest.strip().equals("C")) {
                // a receiver sends 'C' and waits; a shell's text goes on at once
                int more = l.read(buf, 0, buf.length, 200);
                if (more == 0) {
                    return;
                }
                said.append(new String(buf, 0, more, StandardCharsets.ISO_8859_1));
                continue;
            }
            if (echo >= 0 && vehicleText.endsWithPrompt(rest) || n == 0 && !rest.isBlank()) {
                throw new ServiceException(ErrorCode.TRANSFER_FAILED, "the vehicle did not start receiving after '"
                        + vehicleCommand + "'; it said: " + vehicleText.clean(rest, vehicleCommand));
            }
        }
        throw new ServiceException(ErrorCode.TRANSFER_FAILED, "the vehicle did not start receiving within "
                + settings.ymodem().startTimeout().toSeconds() + " s after '" + vehicleCommand + "'");
    }

    private static String describe(List<FileData> files) {
        StringBuilder b = new StringBuilder();
        for (FileData f : files) {
            b.append(b.isEmpty() ? "" : ", ").append(f.name()).append(" (").append(f.total()).append(" bytes)");
        }
        return b.toString();
    }

    // ---- link state

    private void tryOpen() {
        try {
            Link opened = opener.open(settings);
            try {
                settle(opened);
            } catch (IOException e) {
                opened.close();
                throw e;
            }
            link = opened;
            downReason = "";
            log.info("{}: link {} is up", handle, opened.describe());
        } catch (IOException | RuntimeException e) {
            String why = e.getMessage() == null ? e.toString() : e.getMessage();
            if (!why.equals(downReason)) {
                log.warn("{}: cannot open {}: {}", handle, settings.device(), why);
            }
            downReason = why;
        }
    }

    /** Lets a fresh connection's banner pass, so it is not taken for the first reply. */
    private void settle(Link l) throws IOException {
        byte[] buf = new byte[4096];
        long deadline = System.nanoTime() + settings.idleTimeout().toNanos();
        int n;
        while (System.nanoTime() - deadline < 0 && (n = l.read(buf, 0, buf.length, 100)) > 0) {
            log.debug("{}: skipped {} bytes of greeting", handle, n);
        }
    }

    private void linkFailed(Link l, IOException e) {
        if (link == l) {
            link = null;
            downReason = e.getMessage() == null ? e.toString() : e.getMessage();
            log.warn("{}: link {} failed: {}", handle, l.describe(), downReason);
            l.close();
        }
    }

    /** Reopens a down link; on an idle open one, notices a peer that has gone. */
    private void monitor() {
        if (!lock.tryLock()) {
            return; // a command is using the link
        }
        try {
            Link l = link;
            if (l == null) {
                tryOpen();
                return;
            }
            try {
                discardInput(l);
            } catch (IOException e) {
                linkFailed(l, e);
            }
        } catch (RuntimeException e) {
            log.warn("{}: link monitor: {}", handle, e.toString());
        } finally {
            lock.unlock();
        }
    }

    @Override
    public void close() {
        if (monitor != null) {
            monitor.cancel(false);
        }
        lock.lock();
        try {
            Link l = link;
            link = null;
            downReason = "closed";
            if (l != null) {
                l.close();
            }
        } finally {
            lock.unlock();
        }
    }

    private static void deleteTree(Path dir) {
        if (!Files.exists(dir)) {
            return;
        }
        try (Stream<Path> walk = Files.walk(dir)) {
            walk.sorted(Comparator.reverseOrder()).forEach(p -> {
                try {
                    Files.deleteIfExists(p);
                } catch (IOException e) {
                    log.warn("could not delete {}: {}", p, e.toString());
                }
            });
        } catch (IOException e) {
            log.warn("could not clean {}: {}", dir, e.toString());
        }
    }
}
