package org.ripv.client.managers;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.client.handlers.TransferListener;
import org.ripv.messages.ErrorCode;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Owns file work off the UI thread: uploads and downloads with progress and cancel, and saving bytes to a file. */
final class Transfers {
    // Logs under the façade's name, as before the split.
    private static final Logger log = LoggerFactory.getLogger(GuiManager.class);

    private final ClientModel model;
    private final Executor ui;
    private final Executor io;
    private final Supplier<ClientSocketHandler> conn;
    private final GuiInterface gui;
    private final Requests requests;
    private final AtomicLong transferIds = new AtomicLong();

    Transfers(ClientModel model, Executor ui, Executor io, Supplier<ClientSocketHandler> conn, GuiInterface gui,
            Requests requests) {
        this.model = model;
        this.ui = ui;
        this.io = io;
        this.conn = conn;
        this.gui = gui;
        this.requests = requests;
    }

    /** See {@link GuiManager#upload}; on the UI thread. */
    Transfer upload(Path local, ClientSocketHandler.IfExists ifExists) {
        String name = local.getFileName() == null ? local.toString() : local.getFileName().toString();
        Transfer t = new Transfer(transferIds.incrementAndGet(), Transfer.Direction.UPLOAD, name, local, -1);
        run(t, "upload of " + name, h -> {
            long total = Files.size(local);
            ui.execute(() -> {
                t.progress(0, total);
                model.transferChanged(t);
            });
            h.upload(local, name, ifExists, progressOf(t));
            finish(t, Transfer.State.DONE, "uploaded " + name + " to the server's upload directory");
            requests.background("?ulfiles");
        }, e -> {
            if (e.reply().footer().errorCode() == ErrorCode.FILE_EXISTS) {
                ui.execute(() -> t.nameTaken(true)); // the FIM panel asks: keep both, replace or cancel
            }
        });
        return t;
    }

    /** See {@link GuiManager#download}; on the UI thread. */
    Transfer download(String name, Path localDir) {
        Transfer t = new Transfer(transferIds.incrementAndGet(), Transfer.Direction.DOWNLOAD, name, localDir, -1);
        run(t, "download of " + name, h -> {
            Path saved = h.download(name, localDir, progressOf(t));
            finish(t, Transfer.State.DONE, "downloaded " + name + " to " + saved);
        }, e -> { });
        return t;
    }

    /** What a transfer does with the connection. */
    @FunctionalInterface
    private interface Work {
        void run(ClientSocketHandler h) throws IOException, RipvErrorException;
    }

    /**
     * Shows the transfer and runs it on the I/O thread; a refusal ({@code refused} is told first),
     * a failure or a cancel ends it with words that say which.
     */
    private void run(Transfer t, String what, Work work, Consumer<RipvErrorException> refused) {
        model.addTransfer(t);
        io.execute(() -> {
            ClientSocketHandler h = conn.get();
            try {
                if (h == null) {
                    throw new IOException("not connected to a server");
                }
                work.run(h);
            } catch (RipvErrorException e) {
                refused.accept(e);
                finish(t, Transfer.State.FAILED, what + " refused: " + Failures.describe(e));
            } catch (IOException | RuntimeException e) {
                ended(t, what, e);
            }
        });
    }

    /** Shows a transfer's progress as it goes; false (stop) once the operator cancelled it. */
    private TransferListener progressOf(Transfer t) {
        return (done, all) -> {
            ui.execute(() -> {
                t.progress(done, all);
                model.transferChanged(t);
            });
            return !t.cancelRequested();
        };
    }

    /** A transfer that ended by an exception: cancelled if the operator asked, else failed. */
    private void ended(Transfer t, String what, Exception e) {
        finish(t, t.cancelRequested() ? Transfer.State.CANCELLED : Transfer.State.FAILED,
                t.cancelRequested() ? what + " cancelled" : what + " failed: " + Failures.describe(e));
    }

    private void finish(Transfer t, Transfer.State state, String text) {
        if (state == Transfer.State.FAILED) {
            log.warn(text);
        } else {
            log.info(text);
        }
        ui.execute(() -> {
            t.finish(state, text);
            model.transferChanged(t);
            model.notice(text, state == Transfer.State.FAILED);
        });
    }

    /** See {@link GuiManager#save}. */
    void save(Path file, byte[] bytes) {
        io.execute(() -> {
            try {
                Path tmp = Files.createTempFile(file.toAbsolutePath().getParent(), ".ripv-", ".part");
                try {
                    Files.write(tmp, bytes);
                    Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
                } finally {
                    Files.deleteIfExists(tmp);
                }
                gui.showNotice("saved " + file, false);
            } catch (IOException | RuntimeException e) {
                gui.showNotice("could not save " + file + ": " + Failures.describe(e), true);
            }
        });
    }
}
