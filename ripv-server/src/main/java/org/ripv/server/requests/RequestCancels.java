package org.ripv.server.requests;

import java.rmi.RemoteException;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceRegistry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code ?cancel MESSAGE-ID [CLIENT-ID]}: a request still waiting (in the server's queue for its
 * service, or in the service's MailBox) is withdrawn and answered CANCELLED at once; a running
 * one is handed to the service's cancel path, and the final reply it sends is turned into
 * CANCELLED naming who cancelled. The user who sent a request may cancel it; cancelling anyone
 * else's needs a permit rule allowing the {@code ?cancel} command on RIPVServer.
 */
public final class RequestCancels {
    private static final Logger log = LoggerFactory.getLogger(RequestCancels.class);

    private final PendingRequests pending;
    private final ServiceRegistry services;
    private final Supplier<PermitFile> permits;
    private final Consumer<OutgoingServerMessage> outbox;
    private final Consumer<ConsoleEntry> console;
    /** Requests someone asked to cancel while they ran, by pending key: who asked, and when. */
    private final Map<String, Asked> cancelledBy = new ConcurrentHashMap<>();
    /** A cancel whose request then ended another way (timeout, service gone) is forgotten after this. */
    private static final long FORGET_MILLIS = 6 * 3600_000L;

    private record Asked(String user, long at) {}

    /**
     * @param outbox  where the server's replies go (the Post Office's outbox)
     * @param console where the server's own console entries go (who cancelled what)
     */
    public RequestCancels(PendingRequests pending, ServiceRegistry services, Supplier<PermitFile> permits,
                          Consumer<OutgoingServerMessage> outbox, Consumer<ConsoleEntry> console) {
        this.pending = pending;
        this.services = services;
        this.permits = permits;
        this.outbox = outbox;
        this.console = console;
    }

    /** What the canceller hears back. */
    public record Outcome(boolean ok, ErrorCode code, String text) {}

    /** Runs {@code ?cancel}; off the Post Office's thread (it may call the service). */
    public OutgoingServerMessage command(IncomingServerMessage request) {
        String[] w = request.header().body().trim().split("\\s+");
        String user = request.header().origin().user();
        if (w.length < 2 || w.length > 3) {
            return error(request, ErrorCode.BAD_REQUEST, "usage: ?cancel MESSAGE-ID [CLIENT-ID]");
        }
        long id;
        try {
            id = Long.parseLong(w[1]);
        } catch (NumberFormatException e) {
            return error(request, ErrorCode.BAD_REQUEST, "MESSAGE-ID must be a number, got '" + w[1] + "'");
        }
        PendingRequests.Pending p;
        if (w.length == 3) {
            p = pending.get(w[2], id);
        } else {
            p = pending.get(request.header().origin().clientId(), id);
            if (p == null) {
                List<PendingRequests.Pending> mine = pending.withMessageId(id).stream()
                        .filter(x -> x.header().origin().user().equals(user)).toList();
                List<PendingRequests.Pending> any = mine.isEmpty() ? pending.withMessageId(id) : mine;
                if (any.size() > 1) {
                    return error(request, ErrorCode.BAD_REQUEST, any.size() + " requests #" + id + " are running, from clients "
                            + any.stream().map(x -> x.header().origin().clientId()).toList() + "; say which: ?cancel " + id
                            + " CLIENT-ID");
                }
                p = any.isEmpty() ? null : any.get(0);
            }
        }
        if (p == null) {
            return error(request, ErrorCode.BAD_REQUEST, "no request #" + id + (w.length == 3 ? " of client " + w[2] : "")
                    + " is queued or running (it may have finished)");
        }
        String owner = p.header().origin().user();
        if (!owner.equals(user)) {
            PermitFile permits = this.permits.get();
            PermitFile.Decision d = permits.user(user).map(u -> permits.decide(u, ServerReplies.SERVICE, "",
                    request.header().body().trim())).orElse(new PermitFile.Decision(false, "not in the permit file"));
            if (!d.allowed()) {
                return error(request, ErrorCode.FORBIDDEN, "request #" + id + " is " + owner + "'s; user '" + user
                        + "' may not cancel others' requests (" + d.because() + ")");
            }
        }
        Outcome o = cancel(p, user);
        return o.ok() ? request.reply(Footer.ok(Ids.FID_CANCEL, o.text(), null).via(ServerReplies.SERVICE))
                : error(request, o.code(), o.text());
    }

    /** Cancels a request by its sender's client id and message id (a workflow step that timed out). */
    public Outcome cancel(String clientId, long messageId, String byUser) {
        PendingRequests.Pending p = pending.get(clientId, messageId);
        return p == null ? new Outcome(false, ErrorCode.BAD_REQUEST, "not pending") : cancel(p, byUser);
    }

    private Outcome cancel(PendingRequests.Pending p, String byUser) {
        Header h = p.header();
        String what = "#" + h.messageId() + " '" + Header.abbreviate(h.body()) + "' on " + h.mailboxAddress();
        ServiceReference ref = services.find(p.service()).orElse(null);
        if (ref == null) {
            return new Outcome(false, ErrorCode.SERVICE_GONE, p.service() + " is no longer registered");
        }
        String key = PendingRequests.key(h);
        long now = System.currentTimeMillis();
        cancelledBy.values().removeIf(a -> now - a.at() > FORGET_MILLIS);
        cancelledBy.put(key, new Asked(byUser, now));
        try {
            if (ref.withdraw(h)) {
                cancelledBy.remove(key);
                if (pending.complete(h, p.service()) != null) {
                    outbox.accept(new IncomingServerMessage(h).reply(Footer.error(ref.descriptor().sid(), ErrorCode.CANCELLED,
                            "'" + Header.abbreviate(h.body()) + "' was cancelled by " + byUser + " before it ran")
                            .via(ServerReplies.SERVICE)));
                }
                log.info("{} cancelled {} of {} before it ran", byUser, what, h.origin().user());
                transcript(h, byUser, "before it ran");
                return new Outcome(true, ErrorCode.NONE, "cancelled " + what + ": it had not started and will not run");
            }
            if (ref.cancel(h)) {
                log.info("{} cancelled {} of {} while it ran", byUser, what, h.origin().user());
                transcript(h, byUser, "while it ran");
                return new Outcome(true, ErrorCode.NONE, "asked " + p.service() + " to stop " + what
                        + "; its reply will say CANCELLED");
            }
            cancelledBy.remove(key);
            return new Outcome(false, ErrorCode.NOT_AVAILABLE, p.service() + " cannot stop " + what
                    + " while it runs; it will answer when it is done");
        } catch (RemoteException | RuntimeException e) {
            cancelledBy.remove(key);
            return new Outcome(false, ErrorCode.SERVICE_GONE, "could not reach " + p.service() + " to cancel " + what + ": "
                    + e.getMessage());
        }
    }

    /** The MailBox's console and transcript say who cancelled what, and whose it was. */
    private void transcript(Header h, String byUser, String when) {
        try {
            console.accept(ConsoleEntry.command(h.mailboxAddress(), byUser, "?cancel #" + h.messageId() + " '"
                    + Header.abbreviate(h.body()) + "' of " + h.origin().user() + " (" + when + ")"));
        } catch (RuntimeException e) {
            log.warn("could not note the cancel of #{} in the console of {}: {}", h.messageId(), h.mailboxAddress(), e.toString());
        }
    }

    /** A final reply to a request someone cancelled: an ERROR becomes CANCELLED and names them. */
    public Footer judge(PendingRequests.Pending p, Footer f) {
        if (!f.status().isFinal()) {
            return f;
        }
        Asked asked = cancelledBy.remove(PendingRequests.key(p.header()));
        if (asked == null || f.status() != Status.ERROR) {
            return f;
        }
        String by = asked.user();
        String text = f.errorCode() == ErrorCode.CANCELLED ? f.replyText() : f.errorCode() + ": " + f.replyText();
        return new Footer(f.serviceId(), Status.ERROR, ErrorCode.CANCELLED, f.route(), "cancelled by " + by + ": " + text,
                null);
    }

    private static OutgoingServerMessage error(IncomingServerMessage request, ErrorCode code, String text) {
        return request.reply(Footer.error(Ids.FID_CANCEL, code, text).via(ServerReplies.SERVICE));
    }
}
