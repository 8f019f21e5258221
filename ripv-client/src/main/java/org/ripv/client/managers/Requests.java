package org.ripv.client.managers;

import java.io.IOException;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executor;
import java.util.function.BiConsumer;
import java.util.function.Supplier;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.managers.ServiceModel.LineKind;
import org.ripv.messages.Header;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Owns the requests the client sends: off the UI thread, each remembered with the COM panel it came from. */
final class Requests {
    // Logs under the façade's name, as before the split.
    private static final Logger log = LoggerFactory.getLogger(GuiManager.class);

    /** Where a request came from: the service tab whose COM panel sent it, and whether to echo its text. */
    record Origin(String service, boolean echo) {}

    private final ClientModel model;
    private final Executor io;
    private final Supplier<ClientSocketHandler> conn;
    private final GuiInterface gui;
    private final Map<Long, Origin> origins = new ConcurrentHashMap<>();
    /** Requests whose replies go to their caller only (see {@link #ask}), not to the panels. */
    private final Set<Long> quiet = ConcurrentHashMap.newKeySet();
    /**
     * Tracked requests shown as running but not yet written to the socket, by message id: COM
     * shows a request (with Cancel, and Escape) before its I/O thread writes it, so a
     * {@code ?cancel} sent from another I/O thread could reach the server first and be refused
     * ("no request #ID is queued or running"). {@link #cancel} waits for the write.
     */
    private final Map<Long, CompletableFuture<Void>> unwritten = new ConcurrentHashMap<>();

    Requests(ClientModel model, Executor io, Supplier<ClientSocketHandler> conn, GuiInterface gui) {
        this.model = model;
        this.io = io;
        this.conn = conn;
        this.gui = gui;
    }

    /** {@code ?services} and {@code ?mailboxes}: the SEL tree, the tabs and the MAM trees. */
    void refreshServices() {
        background("?services");
        background("?mailboxes");
    }

    /** {@code ?uldir ?dldir ?ulfiles ?dlfiles}: the FIM FileTree. */
    void refreshFiles() {
        background("?uldir");
        background("?dldir");
        background("?ulfiles");
        background("?dlfiles");
    }

    void background(String command) {
        send("", command, Priority.NORMAL, null);
    }

    /**
     * Sends a server command the operator chose from a button (e.g. {@code ?delete NAME}): an OK
     * answer shows in the status bar and runs {@code after}; an ERROR shows there through dispatch.
     */
    void serverAction(String command, Runnable after) {
        io.execute(() -> {
            ClientSocketHandler h = conn.get();
            if (h == null) {
                gui.showNotice("'" + command + "': not connected to a server", true);
                return;
            }
            try {
                h.send("", command, Priority.NORMAL, null).whenComplete((reply, e) -> {
                    if (e != null) {
                        gui.showNotice("'" + command + "' got no reply: " + Failures.describe(e), true);
                    } else if (reply.status() != Status.ERROR) {
                        gui.showNotice(reply.footer().replyText().isBlank() ? command + ": done" : reply.footer().replyText(), false);
                        after.run();
                    }
                });
            } catch (IOException | RuntimeException e) {
                gui.showNotice("'" + command + "' failed: " + Failures.describe(e), true);
            }
        });
    }

    /**
     * Sends a server command in the background and hands its final reply (or the failure) to
     * {@code then}, on the reader or an I/O thread. ERROR replies also reach the status bar
     * through dispatch.
     */
    void call(String command, BiConsumer<OutgoingServerMessage, Throwable> then) {
        io.execute(() -> {
            ClientSocketHandler h = conn.get();
            if (h == null) {
                then.accept(null, new IOException("not connected to a server"));
                return;
            }
            try {
                h.send("", command, Priority.NORMAL, null).whenComplete(then);
            } catch (IOException | RuntimeException e) {
                then.accept(null, e);
            }
        });
    }

    /** See {@link GuiManager#sendCommand}; on the UI thread. */
    void sendCommand(String service, String line) {
        ServiceModel m = model.service(service);
        String command = line == null ? "" : line.strip();
        if (m == null || command.isEmpty()) {
            return;
        }
        if (command.startsWith("?")) {
            m.sent(command);
            model.fire(ClientModel.Kind.COM, service);
            send("", command, m.priority(), new Origin(service, true));
            return;
        }
        if (m.target().isEmpty()) {
            m.append(LineKind.ERROR, "pick a mailbox in the MAM tree first: '" + command + "' was not sent");
            model.fire(ClientModel.Kind.COM, service);
            return;
        }
        m.sent(command);
        model.fire(ClientModel.Kind.COM, service);
        send(m.target(), command, m.priority(), new Origin(service, true));
    }

    /** See {@link GuiManager#selectMailbox}; on the UI thread. */
    void selectMailbox(String service, String mailbox) {
        ServiceModel m = model.service(service);
        if (m == null || mailbox == null || mailbox.equals(m.target())) {
            return;
        }
        String previous = m.target();
        m.target(mailbox);
        model.fire(ClientModel.Kind.COM, service);
        send("", "?status " + mailbox, Priority.NORMAL, new Origin(service, false));
        // The console panel follows the target (docs/sessions.md); a MailBox without a console stays quiet.
        if (!previous.isEmpty()) {
            send("", "?unwatch " + previous, Priority.NORMAL, null);
        }
        send("", "?watch " + mailbox, Priority.NORMAL, null);
    }

    /**
     * Sends a request whose final reply only completes the returned future (the Fleet view's
     * queries): dispatch leaves it alone, so no DAB tab opens for it. Any thread.
     */
    CompletableFuture<OutgoingServerMessage> ask(String mailbox, String body) {
        CompletableFuture<OutgoingServerMessage> out =
                new CompletableFuture<>();
        io.execute(() -> {
            ClientSocketHandler h = conn.get();
            if (h == null) {
                out.completeExceptionally(new IOException("not connected to a server"));
                return;
            }
            Header header = Header.request(h.nextId(), mailbox, body, Priority.NORMAL);
            quiet.add(header.messageId()); // before sending: the reply may beat us back
            try {
                h.send(header, null).whenComplete((reply, e) -> {
                    if (e != null) {
                        quiet.remove(header.messageId());
                        out.completeExceptionally(e);
                    } else {
                        out.complete(reply);
                    }
                });
            } catch (IOException | RuntimeException e) {
                quiet.remove(header.messageId());
                out.completeExceptionally(e);
            }
        });
        return out;
    }

    /** Whether a reply answers an {@link #ask}; forgotten once the reply is final. */
    boolean quiet(long messageId, boolean isFinal) {
        return isFinal ? quiet.remove(messageId) : quiet.contains(messageId);
    }

    /** Where the request a reply answers came from, or null; forgotten once the reply is final. */
    Origin origin(long messageId, boolean isFinal) {
        return isFinal ? origins.remove(messageId) : origins.get(messageId);
    }

    /** Sends off the UI thread; a send that fails is reported where the operator looks. */
    void send(String mailbox, String body, Priority priority, Origin origin) {
        io.execute(() -> {
            ClientSocketHandler h = conn.get();
            if (h == null) {
                failed(origin, body, "not connected to a server");
                return;
            }
            Header header = Header.request(h.nextId(), mailbox, body, priority);
            // A tab's own command to a service runs until its final reply: COM shows it, with Cancel.
            boolean tracked = origin != null && origin.echo() && !mailbox.isEmpty();
            if (origin != null) {
                origins.put(header.messageId(), origin); // before sending: the reply may beat us back
            }
            CompletableFuture<Void> written = new CompletableFuture<>();
            if (tracked) {
                unwritten.put(header.messageId(), written);
                gui.requestStarted(origin.service(), header.messageId(), body);
            }
            try {
                h.send(header, null).whenComplete((reply, e) -> {
                    if (e != null) {
                        origins.remove(header.messageId());
                        failed(origin, body, Failures.describe(e));
                        if (tracked) {
                            gui.requestEnded(origin.service(), header.messageId(), null);
                        }
                    }
                });
            } catch (IOException | RuntimeException e) {
                origins.remove(header.messageId());
                failed(origin, body, Failures.describe(e));
                if (tracked) {
                    gui.requestEnded(origin.service(), header.messageId(), null);
                }
            } finally {
                unwritten.remove(header.messageId());
                written.complete(null);
            }
        });
    }

    /**
     * Sends {@code ?cancel MESSAGE-ID} for a tracked request, as {@link #call} does, but never
     * before the request itself went to the server: the server refuses a cancel of a request it
     * has not seen. Any thread.
     */
    void cancel(long messageId, BiConsumer<OutgoingServerMessage, Throwable> then) {
        CompletableFuture<Void> written = unwritten.get(messageId);
        if (written == null) {
            call("?cancel " + messageId, then); // written already (or never tracked): this write comes after it
        } else {
            written.thenRun(() -> call("?cancel " + messageId, then));
        }
    }

    private void failed(Origin origin, String body, String why) {
        log.debug("'{}' failed: {}", body, why);
        if (origin != null && origin.echo()) {
            gui.showReply(origin.service(), LineKind.ERROR, "'" + body + "' got no reply: " + why);
        }
    }
}
