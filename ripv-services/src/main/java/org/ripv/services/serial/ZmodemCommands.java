package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import org.ripv.exceptions.ServiceException;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileBundle;
import org.ripv.messages.FileData;
import org.ripv.messages.VehicleEvent;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.ripv.services.serial.ymodem.DirectorySink;
import org.ripv.services.serial.ymodem.AskedNames;
import org.ripv.services.serial.ymodem.FileNames;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.TransferListener;
import org.ripv.services.serial.zmodem.ResumeStore;
import org.ripv.services.serial.zmodem.ZmodemException;
import org.ripv.services.serial.zmodem.ZmodemReceiver;
import org.ripv.services.serial.zmodem.ZmodemSender;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code zmodem:get NAME…} and {@code zmodem:put NAME} on one link, with the vehicle's commands
 * from {@link PilotSettings} ({@code zs NAME…}, {@code zr}). As with YMODEM the connection is in
 * binary mode for the exchange and the line is brought back to a clean prompt after it, whatever
 * happened ({@link LineSync}). A get cut by a dropped call keeps its part in the link's
 * {@link ResumeStore}; the next get of that file continues from there.
 */
final class ZmodemCommands {
    private static final Logger log = LoggerFactory.getLogger(ZmodemCommands.class);
    private static final AtomicLong TRANSFERS = new AtomicLong();

    private final String handle;
    private final LinkSettings settings;
    private final PilotSettings pilot;
    private final VehicleText vehicleText;
    private final VehicleConsole console;
    private final Path workDir;
    private final RunningCommand running;
    private final LineSync lineSync;
    private final TransferCancel cancel = new TransferCancel();

    ZmodemCommands(String handle, LinkSettings settings, PilotSettings pilot, VehicleText vehicleText,
                   VehicleConsole console, Path workDir, RunningCommand running) {
        this.handle = handle;
        this.settings = settings;
        this.pilot = pilot;
        this.vehicleText = vehicleText;
        this.console = console;
        this.workDir = workDir;
        this.running = running;
        this.lineSync = new LineSync(settings, new ReplyReader(settings, vehicleText));
    }

    /** ?cancel: the transfer aborts with CANs at its next frame; false when none runs. */
    boolean cancel() {
        return cancel.request();
    }

    /** Where this link's parts wait for the next call (kept across calls; across restarts with --work DIR). */
    ResumeStore resumeStore() throws IOException {
        return new ResumeStore(workDir.resolve("zmodem-parts").resolve(FileNames.requirePlain(handle)));
    }

    private long frameTimeoutMillis() {
        return settings.ymodem().blockTimeout().toMillis();
    }

    private TransferListener listeners(Request request, ProgressReporter progress, String verb, String what, int files) {
        return TransferConsole.listeners(progress, console, request.user(), verb, running.transfer(what, files));
    }

    @FunctionalInterface
    private interface Exchange {
        Reply run() throws IOException, ServiceException;
    }

    /**
     * Binary mode for the exchange; a clean line after it, a TRANSFER_DONE or TRANSFER_FAILED
     * event. A ZMODEM failure or a dropped call is a TRANSFER_FAILED error ending with {@code after}
     * (which parts wait for the next call).
     */
    private Reply transfer(Connection c, Request request, Exchange exchange, Supplier<String> after)
            throws IOException, ServiceException {
        c.listen();
        c.binary(true);
        cancel.started();
        try {
            Reply r = exchange.run();
            console.event(VehicleEvent.TRANSFER_DONE, r.text().lines().findFirst().orElse("") + " for " + request.user());
            return r;
        } catch (ZmodemException e) {
            lineSync.resync(c);
            String why = switch (e.kind()) {
                case REFUSED -> "the vehicle did not start ZMODEM; it said: " + e.getMessage();
                case ABORTED -> e.getMessage() + (request.command().startsWith("zmodem:get")
                        ? "; sz does this when it cannot open the files it was asked for: check their names with dir" : "");
                default -> e.getMessage();
            };
            throw failed(request, why, after);
        } catch (EOFException e) {
            throw failed(request, "the call dropped (" + e.getMessage() + ")", after); // nothing to resync
        } catch (IOException | ServiceException e) {
            lineSync.resync(c);
            throw e;
        } finally {
            cancel.ended();
            c.binary(false);
            c.stopListening();
        }
    }

    private ServiceException failed(Request request, String why, Supplier<String> after) {
        console.transfer(request.user(), "transfer failed: " + why);
        console.event(VehicleEvent.TRANSFER_FAILED, "'" + request.command() + "' for " + request.user() + ": " + why);
        return new ServiceException(ErrorCode.TRANSFER_FAILED, "ZMODEM transfer failed: " + why + after.get());
    }

    Reply get(Connection c, Request request) throws IOException, ServiceException {
        List<String> names = request.arguments();
        if (names.isEmpty()) {
            throw new ServiceException(ErrorCode.BAD_REQUEST, "zmodem:get needs file names, e.g. zmodem:get MISSION1.LOG");
        }
        String vehicleCommand;
        try {
            vehicleCommand = pilot.sendCommand(names);
        } catch (IllegalArgumentException e) {
            throw new ServiceException(ErrorCode.BAD_FILE_NAME, e.getMessage());
        }
        ResumeStore store = resumeStore();
        Path dir = PrivateFiles.createDirectories(workDir).resolve("get-z" + TRANSFERS.incrementAndGet());
        try {
            return transfer(c, request, () -> receive(c, request, names, vehicleCommand, store, dir),
                    () -> kept(store, names));
        } finally {
            DirectorySink.deleteTree(dir);
        }
    }

    /** Says which parts wait for the next call, so the receipt shows what the dropped call did. */
    private static String kept(ResumeStore store, List<String> names) {
        StringBuilder b = new StringBuilder();
        for (String n : names) {
            try {
                long have = n.contains("*") || n.contains("?") ? -1 : store.partLength(n);
                if (have > 0) {
                    b.append("; kept ").append(have).append(" bytes of ").append(n)
                            .append(" (not complete): the next zmodem:get ").append(n).append(" continues from there");
                }
            } catch (IOException | IllegalArgumentException e) {
                // no part to report
            }
        }
        return b.toString();
    }

    private Reply receive(Connection c, Request request, List<String> names, String vehicleCommand, ResumeStore store,
                          Path dir) throws IOException, ServiceException {
        PrivateFiles.createDirectories(dir);
        write(c, vehicleCommand);
        ProgressReporter progress = new ProgressReporter(request, "receiving");
        boolean globs = names.stream().anyMatch(n -> n.contains("*") || n.contains("?"));
        List<ZmodemReceiver.Received> got = new ZmodemReceiver(c, frameTimeoutMillis(),
                listeners(request, progress, "receiving", "zmodem:get", globs ? -1 : names.size()))
                .startTimeout(settings.ymodem().startTimeout().toMillis())
                .cancelWhen(cancel::requested)
                .refusedWhen(text -> vehicleText.promptAfterEcho(text, vehicleCommand))
                .receive(store, dir);
        lineSync.resync(c);
        if (got.isEmpty()) {
            throw new ServiceException(ErrorCode.TRANSFER_FAILED, "the vehicle sent no files for '" + String.join(" ", names)
                    + "' (does it have them?)");
        }
        AskedNames.Verdict verdict = new AskedNames(names).check(got.stream().map(ZmodemReceiver.Received::file).toList());
        verdict.warnings().forEach(w -> log.warn("{}: {}", handle, w));
        if (verdict.accepted().isEmpty()) {
            throw new ServiceException(ErrorCode.TRANSFER_FAILED, "the vehicle sent none of '" + String.join(" ", names) + "'");
        }
        List<ZmodemReceiver.Received> kept = verdict.accepted().stream().map(a -> got.stream()
                .filter(x -> x.file().name().equals(a.file().name())).findFirst().orElseThrow()).toList();
        ReceivedFiles.checkFits("zmodem:get", kept.stream().map(ZmodemReceiver.Received::path).toList(), ReceivedFiles.budget());
        List<FileData> data = new ArrayList<>();
        StringBuilder text = new StringBuilder("received ");
        long bytes = 0;
        for (int i = 0; i < kept.size(); i++) {
            AskedNames.Accepted a = verdict.accepted().get(i);
            ZmodemReceiver.Received r = kept.get(i);
            byte[] content = Files.readAllBytes(r.path());
            bytes += content.length - r.resumedAt();
            data.add(FileData.whole(a.storedName(), content));
            text.append(data.size() > 1 ? ", " : "").append(a.storedName()).append(" (").append(content.length)
                    .append(" bytes").append(r.note().isEmpty() ? "" : "; " + r.note()).append(')');
        }
        text.append(" in ").append(progress.summary(bytes));
        verdict.warnings().forEach(w -> text.append("\nwarning: ").append(w));
        log.info("{}: {}", handle, text);
        return Reply.ok(text.toString(), data.size() == 1 ? data.get(0) : new FileBundle(data));
    }

    Reply put(Connection c, Request request) throws IOException, ServiceException {
        return put(c, request, PutFile.of(request, "zmodem:put"));
    }

    /** Sends one file, however it was named (a to-vehicle file comes as {@code to-vehicle/FOLDER/NAME}). */
    Reply put(Connection c, Request request, SendFile file) throws IOException, ServiceException {
        return transfer(c, request, () -> send(c, request, file), () -> "");
    }

    /** Sends one file to the vehicle's {@code zr}. */
    Reply send(Connection c, Request request, SendFile file) throws IOException {
        write(c, pilot.zmodemReceive());
        ProgressReporter progress = new ProgressReporter(request, "sending");
        long from = new ZmodemSender(c, frameTimeoutMillis(), listeners(request, progress, "sending", "zmodem:put", 1))
                .startTimeout(settings.ymodem().startTimeout().toMillis())
                .cancelWhen(cancel::requested)
                .refusedWhen(text -> vehicleText.promptAfterEcho(text, pilot.zmodemReceive()))
                .send(file);
        lineSync.resync(c);
        String text = "sent " + file.name() + " (" + file.length() + " bytes" + (from > 0 ? "; the vehicle had "
                + from + " already and took the rest" : "") + ") in " + progress.summary(file.length() - from);
        log.info("{}: {}", handle, text);
        return Reply.ok(text);
    }

    private void write(Connection c, String vehicleCommand) throws IOException {
        c.write((vehicleCommand + settings.lineEnding()).getBytes(StandardCharsets.ISO_8859_1));
        c.flush();
    }
}
