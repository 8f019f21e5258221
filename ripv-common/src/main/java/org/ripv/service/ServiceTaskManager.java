package org.ripv.service;

import org.ripv.exceptions.ServiceException;
import org.ripv.managers.TaskManager;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.post.MailBox;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** A service's TaskManager (thesis figure 5.4): header side runs the handler, footer side replies. */
final class ServiceTaskManager extends TaskManager<IncomingServiceMessage, OutgoingServiceMessage> {
    private static final Logger log = LoggerFactory.getLogger(ServiceTaskManager.class);

    private final RIPVService service;
    private final CommandHandler handler;

    ServiceTaskManager(RIPVService service, CommandHandler handler) {
        this.service = service;
        this.handler = handler;
    }

    @Override
    public void parseHeader(MailBox<IncomingServiceMessage, OutgoingServiceMessage> box, IncomingServiceMessage request)
            throws Exception {
        Reply r = handler.execute(new Request(request, box, service.sid(), service.name().toString()));
        if (r == null) {
            throw new IllegalStateException("the handler of " + box.address() + " returned no reply");
        }
        box.post(request.reply(new Footer(service.sid(), r.status(), r.code(), null, r.text(), r.result())
                .via(service.name().toString())));
    }

    @Override
    public void parseFooter(MailBox<IncomingServiceMessage, OutgoingServiceMessage> box, OutgoingServiceMessage reply)
            throws Exception {
        service.sink().reply(reply);
    }

    @Override
    public void parseFooters(MailBox<IncomingServiceMessage, OutgoingServiceMessage> box, java.util.List<OutgoingServiceMessage> replies) {
        try {
            service.sink().replies(java.util.List.copyOf(replies));
        } catch (Exception e) {
            replies.forEach(r -> undeliverable(box, r, e));
        }
    }

    @Override
    public void failed(MailBox<IncomingServiceMessage, OutgoingServiceMessage> box, IncomingServiceMessage request,
                       Throwable cause) {
        ErrorCode code = cause instanceof ServiceException se ? se.code() : ErrorCode.INTERNAL;
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
