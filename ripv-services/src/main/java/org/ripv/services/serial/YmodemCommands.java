package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.exceptions.ServiceException;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileBundle;
import org.ripv.messages.FileData;
import org.ripv.messages.VehicleEvent;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.ripv.services.serial.ymodem.AskedNames;
import org.ripv.services.serial.ymodem.DirectorySink;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.FileNames;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.YmodemReceiver;
import org.ripv.services.serial.ymodem.YmodemRefusedException;
import org.ripv.services.serial.ymodem.YmodemSender;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code ymodem:get NAME…} and {@code ymodem:put NAME} on one link. The connection is in binary
 * mode for the whole exchange, so the console shows TRANSFER lines and a TRANSFER_DONE or
 * TRANSFER_FAILED event, never the blocks.
 */
final class YmodemCommands {
    private static final Logger log = LoggerFactory.getLogger(YmodemCommands.class);
    private static final AtomicLong TRANSFERS = new AtomicLong();
    /** How many more times a transfer start the vehicle refused is tried, after a resync (the {@code Cyr} story). */
    static final int START_RETRIES = 1;

    private final String handle;
    private final LinkSettings settings;
    private final VehicleText vehicleText;
    private final ReplyReader replies;
    private final VehicleConsole console;
    private final Path workDir;
    private final RunningCommand running;
    private final LineSync lineSync;
    private final TransferCancel cancel = new TransferCancel();

    YmodemCommands(String handle, LinkSettings settings, VehicleText vehicleText, VehicleConsole console, Path workDir,
                   RunningCommand running) {
        this.running = running;
        this.handle = handle;
        this.settings = settings;
        this.vehicleText = vehicleText;
        this.replies = new ReplyReader(settings, vehicleText);
        this.lineSync = new LineSync(settings, replies);
        this.console = console;
        this.workDir = workDir;
    }

    /**
     * Cancels the running transfer (?cancel, from another thread): it aborts with CAN CAN before
     * its next block, and the line is brought back to the prompt as after any failed transfer.
     *
     * @return false when no transfer is running
     */
    boolean cancel() {
        return cancel.request();
    }

    /**
     * Runs a transfer in binary mode and reports its end on the console. The exchange leaves a
     * clean line when it succeeds ({@link LineSync}); here it is made clean after a failure or a
     * cancel, so the next command always meets the vehicle's prompt.
     */
    private Reply transfer(Connection c, Request request, Exchange exchange) throws IOException, ServiceException {
        c.listen();
        c.binary(true);
        try {
            Reply r = exchange.run();
            console.event(VehicleEvent.TRANSFER_DONE, r.text() + " for " + request.user());
            return r;
        } catch (ServiceException | IOException e) {
            if (!(e instanceof EOFException)) {
                resync(c);
            }
            String why = e.getMessage();
            console.transfer(request.user(), "transfer failed: " + why);
            console.event(VehicleEvent.TRANSFER_FAILED, "'" + request.command() + "' for " + request.user() + ": " + why);
            throw e;
        } finally {
            c.binary(false);
            c.stopListening();
        }
    }

    /** After a failed or cancelled transfer, lets the vehicle finish and brings its line back to a clean prompt. */
    private void resync(Connection c) {
        try {
            if (!lineSync.resync(c)) {
                log.info("{}: the vehicle did not show its prompt after a failed transfer", handle);
            }
        } catch (IOException e) {
            log.debug("{}: link failed after a failed transfer: {}", handle, e.toString()); // the reader reports it
        }
    }

    @FunctionalInterface
    private interface Exchange {
        Reply run() throws IOException, ServiceException;
    }

    Reply get(Connection c, Request request) throws IOException, ServiceException {
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
        return transfer(c, request, () -> receive(c, request, names));
    }

    /** Makes the work directory owner-only and removes partial files an earlier, killed run left. */
    void prepareWorkDir() {
        DirectorySink.prepareWorkDir(workDir);
    }

    private Reply receive(Connection c, Request request, List<String> names) throws IOException, ServiceException {
        Path dir = PrivateFiles.createDirectories(workDir).resolve("get-" + TRANSFERS.incrementAndGet());
        try {
            DirectorySink sink = new DirectorySink(dir);
            String vehicleCommand = settings.sendCommand() + " " + String.join(" ", names);
            ProgressReporter progress = new ProgressReporter(request, "receiving");
            List<FileHeader> files = null;
            cancel.started();
            try {
                for (int attempt = 0; files == null; attempt++) {
                    write(c, vehicleCommand);
                    try {
                        files = new YmodemReceiver(c, settings.ymodem(), TransferConsole.listeners(progress, console,
                                request.user(), "receiving", running.transfer("ymodem:get", names.stream()
                                        .anyMatch(n -> n.contains("*") || n.contains("?")) ? -1 : names.size())))
                                .cancelWhen(cancel::requested)
                                .stopWaitingWhen(text -> vehicleText.promptAfterEcho(text, vehicleCommand)).receiveBatch(sink);
                    } catch (YmodemRefusedException e) {
                        if (attempt >= START_RETRIES || cancel.requested()) {
                            throw e;
                        }
                        refused(c, request, vehicleCommand, e.getMessage());
                    }
                }
            } finally {
                cancel.ended();
            }
            lineSync.resync(c);
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
            ReceivedFiles.checkFits("ymodem:get", verdict.accepted().stream().map(a -> dir.resolve(a.file().name())).toList(),
                    ReceivedFiles.budget());
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
            DirectorySink.deleteTree(dir);
        }
    }

    Reply put(Connection c, Request request) throws IOException, ServiceException {
        return put(c, request, PutFile.of(request, "ymodem:put"));
    }

    /** Sends one file, however it was named (a to-vehicle file comes as {@code to-vehicle/FOLDER/NAME}). */
    Reply put(Connection c, Request request, SendFile file) throws IOException, ServiceException {
        return transfer(c, request, () -> {
            for (int attempt = 0; ; attempt++) {
                write(c, settings.receiveCommand());
                String refusal = awaitReceiver(c, settings.receiveCommand());
                if (refusal == null) {
                    break;
                }
                String why = "the vehicle did not start receiving after '" + settings.receiveCommand() + "'; it said: " + refusal;
                if (attempt >= START_RETRIES) {
                    throw new ServiceException(ErrorCode.TRANSFER_FAILED, why + (attempt > 0 ? " (tried "
                            + (attempt + 1) + " times, with a clean line before each)" : ""));
                }
                refused(c, request, settings.receiveCommand(), why);
            }
            ProgressReporter progress = new ProgressReporter(request, "sending");
            cancel.started();
            try {
                new YmodemSender(c, settings.ymodem(), TransferConsole.listeners(progress, console, request.user(),
                        "sending", running.transfer("ymodem:put", 1)))
                        .cancelWhen(cancel::requested).sendBatch(List.of(file), true);
            } finally {
                cancel.ended();
            }
            lineSync.resync(c);
            String text = "sent " + file.name() + " (" + file.length() + " bytes) in " + progress.summary(file.length());
            log.info("{}: {}", handle, text);
            return Reply.ok(text);
        });
    }

    /** The vehicle refused a transfer's start: say so, clean its line, and let the caller try once more. */
    private void refused(Connection c, Request request, String vehicleCommand, String why) throws IOException {
        log.info("{}: '{}' was refused ({}); resynchronising with the prompt and trying once more", handle, vehicleCommand, why);
        console.transfer(request.user(), "'" + vehicleCommand + "' was refused; trying once more on a clean line");
        lineSync.resync(c);
    }

    private void write(Connection c, String vehicleCommand) throws IOException {
        c.write((vehicleCommand + settings.lineEnding()).getBytes(StandardCharsets.ISO_8859_1));
        c.flush();
    }

    /**
     * Reads past the echo of the vehicle's receive command until its YMODEM receiver asks with a
     * lone 'C' (returns null). A shell that answers with text instead ("Bad command", then its
     * prompt, which holds a 'C' too) is a refusal: its text is returned, rather than block 0
     * being typed at it.
     */
    private String awaitReceiver(Link l, String vehicleCommand) throws IOException, ServiceException {
        StringBuilder said = new StringBuilder();
        byte[] buf = new byte[512];
        long deadline = System.nanoTime() + settings.ymodem().startTimeout().toNanos();
        while (System.nanoTime() - deadline < 0) {
            int n = l.read(buf, 0, buf.length, settings.idleTimeout().toMillis());
            if (n > 0 && said.length() < 64 * 1024) {
                said.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
            }
            int echo = VehicleText.echoEnd(said, vehicleCommand);
            String rest = echo >= 0 ? said.substring(echo) : said.toString();
            if (rest.strip().equals("C")) {
                // a receiver sends 'C' and waits; a shell's text goes on at once
                int more = l.read(buf, 0, buf.length, 200);
                if (more == 0) {
                    return null;
                }
                said.append(new String(buf, 0, more, StandardCharsets.ISO_8859_1));
                continue;
            }
            if (echo >= 0 && vehicleText.endsWithPrompt(rest) || n == 0 && !rest.isBlank()) {
                return vehicleText.clean(rest, vehicleCommand);
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
}
