package org.ripv.service;

import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.ripv.exceptions.ServiceException;
import org.ripv.managers.TaskManager;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;
import org.ripv.messages.TablePages;
import org.ripv.post.MailBox;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** A service's TaskManager (thesis figure 5.4): header side runs the handler, footer side replies. */
final class ServiceTaskManager extends TaskManager<IncomingServiceMessage, OutgoingServiceMessage> {
    private static final Logger log = LoggerFactory.getLogger(ServiceTaskManager.class);

    private final RIPVService service;
    private final CommandHandler handler;
    /** The request running now (one at a time per MailBox), for cancel; null between requests. */
    private volatile Request running;
    private volatile boolean cancelled;
    /**
     * Cancels that came before their request ran (it was on its way from the server, or waiting
     * in the MailBox): "CLIENT-ID#MESSAGE-ID" to when it was asked, oldest first. Guarded by
     * {@code this}; bounded in number and age, since a cancel may name a request that never comes.
     */
    private final Map<String, Long> cancelledAhead = new LinkedHashMap<>();
    static final int MAX_CANCELLED_AHEAD = 256;
    static final long CANCELLED_AHEAD_MILLIS = 10 * 60_000L;
    /**
     * The last requests that came up here ("CLIENT-ID#MESSAGE-ID"), so that a cancel of one that has
     * already ended is refused ("nothing left to cancel") instead of being kept for a request that
     * will never come again. Guarded by {@code this}; the newest {@link #MAX_SEEN} only.
     */
    private final Map<String, Boolean> seen = new LinkedHashMap<>() {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Boolean> eldest) {
            return size() > MAX_SEEN;
        }
    };
    static final int MAX_SEEN = 1024;

    ServiceTaskManager(RIPVService service, CommandHandler handler) {
        this.service = service;
        this.handler = handler;
    }

    @Override
    public void parseHeader(MailBox<IncomingServiceMessage, OutgoingServiceMessage> box, IncomingServiceMessage request)
            throws Exception {
        // Tickets in place of files: read the files from the services that hold them first (org.ripv.handout).
        request = service.handouts().collect(request);
        Request now = new Request(request, box, service.sid(), service.name().toString());
        synchronized (this) {
            String key = key(request.header().origin().clientId(), request.header().messageId());
            seen.put(key, Boolean.TRUE);
            if (cancelledAhead.remove(key) != null) {
                box.post(request.reply(Footer.error(service.sid(), ErrorCode.CANCELLED, "'"
                        + Header.abbreviate(request.header().body()) + "' was cancelled before it ran")
                        .via(service.name().toString())));
                return;
            }
            cancelled = false;
            running = now;
        }
        Reply r;
        boolean wasCancelled;
        try {
            r = handler.execute(now);
        } finally {
            synchronized (this) {
                running = null;
                wasCancelled = cancelled;
            }
        }
        if (r == null) {
            throw new IllegalStateException("the handler of " + box.address() + " returned no reply");
        }
        ErrorCode code = wasCancelled && r.status() == Status.ERROR ? ErrorCode.CANCELLED : r.code();
        if (r.status() == Status.OK) {
            service.handouts().keep(r.result()); // before the reply leaves: the server may sign tickets for it at once
        }
        box.post(request.reply(new Footer(service.sid(), r.status(), code, null, r.text(), r.result())
                .via(service.name().toString())));
    }

    /**
     * Cancels the request named: the running one through its handler (true when the handler
     * accepted); one that has not started yet — waiting in the MailBox, or still on its way from
     * the server, whose queue the operator's cancel can overtake — is answered CANCELLED when it
     * comes up and never runs (true); one that has already ended is refused (false). Under the manager's lock, so that a cancel never lands on
     * another request.
     */
    synchronized boolean cancel(String clientId, long messageId) {
        Request r = running;
        if (r == null || r.message().header().messageId() != messageId
                || !r.message().header().origin().clientId().equals(clientId)) {
            if (seen.containsKey(key(clientId, messageId))) {
                return false; // it came up and ended: nothing left to cancel
            }
            cancelAhead(clientId, messageId);
            return true;
        }
        boolean taken = handler.cancel(r);
        cancelled = taken;
        if (taken) {
            r.stopPages();
        }
        return taken;
    }

    private void cancelAhead(String clientId, long messageId) {
        long now = System.currentTimeMillis();
        for (Iterator<Long> it = cancelledAhead.values().iterator(); it.hasNext(); ) {
            if (now - it.next() <= CANCELLED_AHEAD_MILLIS) {
                break; // oldest first: the rest are younger
            }
            it.remove();
        }
        if (cancelledAhead.size() >= MAX_CANCELLED_AHEAD) {
            Iterator<String> oldest = cancelledAhead.keySet().iterator();
            oldest.next();
            oldest.remove();
        }
        cancelledAhead.put(key(clientId, messageId), now);
    }

    private static String key(String clientId, long messageId) {
        return clientId + "#" + messageId;
    }

    /** The reader took a page of the request running now (the server's {@code more}); false when it is not running. */
    boolean pageTaken(String clientId, long messageId) {
        Request r = running;
        if (r == null || r.message().header().messageId() != messageId
                || !r.message().header().origin().clientId().equals(clientId)) {
            return false;
        }
        r.pageTaken();
        return true;
    }

    /** For a sink that does not pace pages, handing a page over is the reader taking it. */
    private void handedOver(OutgoingServiceMessage reply) {
        if (TablePages.isPage(reply.footer()) && !service.sink().pacesPages()) {
            pageTaken(reply.header().origin().clientId(), reply.header().messageId());
        }
    }

    @Override
    public void parseFooter(MailBox<IncomingServiceMessage, OutgoingServiceMessage> box, OutgoingServiceMessage reply)
            throws Exception {
        service.sink().reply(reply);
        handedOver(reply);
    }

    @Override
    public void parseFooters(MailBox<IncomingServiceMessage, OutgoingServiceMessage> box, List<OutgoingServiceMessage> replies) {
        try {
            service.sink().replies(List.copyOf(replies));
            replies.forEach(this::handedOver);
        } catch (Exception e) {
            replies.forEach(r -> undeliverable(box, r, e));
        }
    }

    @Override
    public void failed(MailBox<IncomingServiceMessage, OutgoingServiceMessage> box, IncomingServiceMessage request,
                       Throwable cause) {
        ErrorCode code = cancelled ? ErrorCode.CANCELLED : cause instanceof ServiceException se ? se.code() : ErrorCode.INTERNAL;
        String text = cause.getMessage() == null ? cause.toString() : cause.getMessage();
        box.post(request.reply(Footer.error(service.sid(), code, text).via(service.name().toString())));
    }

    @Override
    public void undeliverable(MailBox<IncomingServiceMessage, OutgoingServiceMessage> box, OutgoingServiceMessage reply,
                              Throwable cause) {
        log.warn("reply to #{} from {} lost: the server could not be reached ({})",
                reply.header().messageId(), reply.header().origin().clientId(), cause.toString());
    }
}
