package org.ripv.server.routing;

import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.requests.ServerReplies;
import org.ripv.server.services.ServiceReference;

/**
 * A request on its way through the {@link Admission} steps, and what the steps have found out
 * about it so far: each step reads what the ones before it set and may add its own finding.
 */
public final class Admitting {
    private final IncomingServerMessage request;
    private MailboxAddress address;
    private ServiceReference service;
    private PermitFile.User user;
    private Attachment attachment;

    public Admitting(IncomingServerMessage request) {
        this.request = request;
    }

    public IncomingServerMessage request() {
        return request;
    }

    /** The command line, as the client sent it. */
    public String body() {
        return request.header().body();
    }

    /** Who sent it (the name on the client's badge). */
    public String userName() {
        return request.header().origin().user();
    }

    /** Set by {@link MailboxChosen}. */
    public MailboxAddress address() {
        return address;
    }

    void address(MailboxAddress a) {
        this.address = a;
    }

    /** Set by {@link ServiceRegistered}. */
    public ServiceReference service() {
        return service;
    }

    void service(ServiceReference ref) {
        this.service = ref;
    }

    /** Set by {@link UserKnown}. */
    public PermitFile.User user() {
        return user;
    }

    void user(PermitFile.User u) {
        this.user = u;
    }

    /** Set by {@link AttachmentRule}: the file(s) the command names, or null. */
    public Attachment attachment() {
        return attachment;
    }

    void attachment(Attachment a) {
        this.attachment = a;
    }

    /** The service's SID once it is known, else the FID of no command ({@code 000000}): what a refusal names. */
    public String sid() {
        return service == null ? Ids.FID_NONE : service.descriptor().sid();
    }

    /** The ERROR reply that refuses this request. */
    public OutgoingServerMessage refuse(ErrorCode code, String text) {
        return ServerReplies.error(request, sid(), code, text);
    }
}
