package org.ripv.client.managers;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.Executor;
import java.util.function.Supplier;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The workflow queue as the GUI changes it (docs/workflows.md): {@code ?queue}, {@code ?receipts},
 * and adding a workflow — a file from this computer or text written in the GUI — by uploading it
 * and then {@code ?queue add MAILBOX NAME}. Network work runs on the I/O threads; the
 * {@link WorkflowModel} changes on the UI executor.
 */
final class WorkflowActions {
    private static final Logger log = LoggerFactory.getLogger(WorkflowActions.class);

    private final WorkflowModel model;
    private final Executor ui;
    private final Executor io;
    private final Supplier<ClientSocketHandler> conn;

    WorkflowActions(WorkflowModel model, Executor ui, Executor io, Supplier<ClientSocketHandler> conn) {
        this.model = model;
        this.ui = ui;
        this.io = io;
        this.conn = conn;
    }

    void refresh(String mailbox, int lastReceipts) {
        io.execute(() -> {
            try {
                OutgoingServerMessage q = call("?queue " + mailbox);
                if (q.status() == Status.ERROR) {
                    ui.execute(() -> model.outcome(mailbox, q.footer().replyText(), true));
                } else {
                    ui.execute(() -> model.listing(mailbox, q.footer().replyText()));
                }
                OutgoingServerMessage r = call("?receipts " + mailbox + " --last " + lastReceipts);
                if (r.status() != Status.ERROR) {
                    ui.execute(() -> model.receipts(mailbox, r.footer().replyText()));
                }
            } catch (IOException | RuntimeException e) {
                failed(mailbox, "?queue " + mailbox, e);
            }
        });
    }

    void remove(String mailbox, long id) {
        change(mailbox, "?queue remove " + mailbox + " " + id);
    }

    void clear(String mailbox) {
        change(mailbox, "?queue clear " + mailbox);
    }

    /** Uploads a workflow file under its own name, then queues it. */
    void addFile(String mailbox, Path local, ClientSocketHandler.IfExists ifExists) {
        String name = local.getFileName() == null ? local.toString() : local.getFileName().toString();
        io.execute(() -> uploadAndQueue(mailbox, local, name, ifExists, false));
    }

    /** Uploads text written in the GUI as NAME, then queues it. */
    void addText(String mailbox, String name, String text, ClientSocketHandler.IfExists ifExists) {
        io.execute(() -> {
            Path tmp = null;
            try {
                tmp = Files.createTempFile("ripv-workflow-", ".wf");
                Files.writeString(tmp, text, StandardCharsets.UTF_8);
                uploadAndQueue(mailbox, tmp, name, ifExists, true);
            } catch (IOException e) {
                failed(mailbox, "writing " + name, e);
            } finally {
                if (tmp != null) {
                    try {
                        Files.deleteIfExists(tmp);
                    } catch (IOException e) {
                        log.debug("could not delete {}: {}", tmp, e.toString());
                    }
                }
            }
        });
    }

    /** @param typed written in the GUI: a refused one leaves the upload store again ({@code ?queue add … --typed}) */
    private void uploadAndQueue(String mailbox, Path local, String name, ClientSocketHandler.IfExists ifExists, boolean typed) {
        try {
            ClientSocketHandler h = connection();
            String stored = name;
            try {
                OutgoingServerMessage up = h.upload(local, name, ifExists, null);
                if (up.footer().result() instanceof FileListing l && !l.files().isEmpty()) {
                    stored = l.files().get(0).name(); // after "keep": the new free name
                }
            } catch (RipvErrorException e) {
                String why = e.reply().footer().replyText();
                if (e.reply().footer().errorCode() == ErrorCode.FILE_EXISTS) {
                    ui.execute(() -> model.nameTaken(mailbox, name, why));
                } else {
                    ui.execute(() -> model.outcome(mailbox, "upload of " + name + " refused: " + why, true));
                }
                return;
            }
            change(h, mailbox, "?queue add " + mailbox + " " + stored + (typed ? " --typed" : ""));
        } catch (IOException | RuntimeException e) {
            failed(mailbox, "upload of " + name, e);
        }
    }

    private void change(String mailbox, String command) {
        io.execute(() -> {
            try {
                change(connection(), mailbox, command);
            } catch (IOException | RuntimeException e) {
                failed(mailbox, command, e);
            }
        });
    }

    /** Sends a change; its answer is the outcome, and the queue and receipts are asked again. */
    private void change(ClientSocketHandler h, String mailbox, String command) throws IOException {
        OutgoingServerMessage r = h.call("", command, Priority.NORMAL, Duration.ofSeconds(60), null);
        boolean error = r.status() == Status.ERROR;
        String text = r.footer().replyText();
        String first = text.lines().findFirst().orElse(error ? "refused" : "done");
        ui.execute(() -> model.outcome(mailbox, error ? text + " [" + r.footer().errorCode() + "]" : first, error));
        refresh(mailbox, 20);
    }

    private OutgoingServerMessage call(String command) throws IOException {
        return connection().call("", command, Priority.NORMAL, Duration.ofSeconds(60), null);
    }

    private ClientSocketHandler connection() throws IOException {
        ClientSocketHandler h = conn.get();
        if (h == null) {
            throw new IOException("not connected to a server");
        }
        return h;
    }

    private void failed(String mailbox, String what, Exception e) {
        String why = what + " failed: " + Failures.describe(e);
        log.info(why);
        ui.execute(() -> model.outcome(mailbox, why, true));
    }
}
