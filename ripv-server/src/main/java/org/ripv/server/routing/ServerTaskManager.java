package org.ripv.server.routing;

import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Predicate;
import org.ripv.managers.TaskManager;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;
import org.ripv.post.MailBox;
import org.ripv.server.clients.WaitingRequests;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.requests.ServerReplies;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The RIPV Post Office's TaskManager (thesis figure 5.3). Header side: a {@code ?} command runs
 * in the server's commands; anything else goes through {@link Admission} to its service.
 * Footer side: a workflow step's reply goes to its runner, any other to the client that asked,
 * or is dropped and logged when that client has gone.
 */
public final class ServerTaskManager extends TaskManager<IncomingServerMessage, OutgoingServerMessage> {
    private static final Logger log = LoggerFactory.getLogger(ServerTaskManager.class);

    private final Consumer<IncomingServerMessage> commands;
    private final Admission admission;
    private final Predicate<OutgoingServerMessage> workflowReplies;
    private final WaitingRequests waiting;
    private final Function<String, Optional<SocketHandler>> clients;
    private final Consumer<OutgoingServerMessage> outbox;

    /**
     * @param commands        runs a {@code ?} command
     * @param workflowReplies takes a workflow step's reply (true), or leaves it (false)
     * @param waiting         each client's requests waiting for their final reply
     * @param clients         the connected client of an id
     * @param outbox          where a refusal goes (the Post Office's outbox)
     */
    public ServerTaskManager(Consumer<IncomingServerMessage> commands, Admission admission,
                             Predicate<OutgoingServerMessage> workflowReplies, WaitingRequests waiting,
                             Function<String, Optional<SocketHandler>> clients, Consumer<OutgoingServerMessage> outbox) {
        this.commands = commands;
        this.admission = admission;
        this.workflowReplies = workflowReplies;
        this.waiting = waiting;
        this.clients = clients;
        this.outbox = outbox;
    }

    @Override
    public void parseHeader(MailBox<IncomingServerMessage, OutgoingServerMessage> box, IncomingServerMessage request) {
        if (request.header().isServerCommand()) {
            commands.accept(request);
            return;
        }
        OutgoingServerMessage refusal = admission.route(request);
        if (refusal != null) {
            outbox.accept(refusal);
        }
    }

    @Override
    public void parseFooter(MailBox<IncomingServerMessage, OutgoingServerMessage> box, OutgoingServerMessage reply) {
        if (workflowReplies.test(reply)) {
            return; // a workflow step's reply: the runner judges it
        }
        if (reply.footer().status() != Status.PROGRESS) {
            waiting.done(reply.header().origin().clientId(), reply.header()); // its final reply: no longer waiting
        }
        Optional<SocketHandler> client = clients.apply(reply.header().origin().clientId());
        if (client.isEmpty()) {
            log.info("dropped reply to #{}: client {} has disconnected", reply.header().messageId(),
                    reply.header().origin().clientId());
            return;
        }
        client.get().send(reply);
    }

    @Override
    public void failed(MailBox<IncomingServerMessage, OutgoingServerMessage> box, IncomingServerMessage request,
                       Throwable cause) {
        outbox.accept(ServerReplies.error(request, Ids.FID_NONE, ErrorCode.INTERNAL, "the server failed on '"
                + Header.abbreviate(request.header().body()) + "': " + cause));
    }
}
