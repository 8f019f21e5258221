package org.ripv.server.routing;

import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.ripv.messages.Header;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.server.dataloop.DataLoop;
import org.ripv.server.files.FileStore;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.requests.RequestForwarder;
import org.ripv.server.services.ServiceRegistry;

/**
 * Admission of a request to a service (thesis figure 5.3, parseHeader: "search for service in
 * ServiceReferences … serviceRequest(message)"): the request passes each {@link AdmissionStep} in
 * turn and is forwarded, or the first step that refuses it says why. The order matters: a
 * request is parsed before its service is looked up, one line before any permit rule reads it,
 * the user and the rules before the lock, and files are read last, only for a request that may go.
 */
public final class Admission {
    private final List<AdmissionStep> steps;
    private final RequestForwarder forwarder;

    /** The steps in order: mailbox, service, one line, user known, permit, lock, plot takeover, to-vehicle folder, attachment. */
    public static List<AdmissionStep> steps(ServiceRegistry services, Supplier<PermitFile> permits, Map<String, OperatorLock> locks,
                                            DataLoop dataLoop, FileStore files, Consumer<OutgoingServerMessage> outbox) {
        return List.of(new MailboxChosen(), new ServiceRegistered(services), new OneLine(), new UserKnown(permits),
                new PermitAllows(permits), new LockFree(locks), new PlotTakeover(dataLoop, outbox), new ToVehicleFolderRule(),
                new AttachmentRule(files, permits));
    }

    public Admission(List<AdmissionStep> steps, RequestForwarder forwarder) {
        this.steps = List.copyOf(steps);
        this.forwarder = forwarder;
    }

    /** Forwards the request, or returns the error reply that refuses it (null: forwarded, or answered already). */
    public OutgoingServerMessage route(IncomingServerMessage request) {
        Admitting a = new Admitting(request);
        for (AdmissionStep step : steps) {
            AdmissionStep.Verdict v = step.check(a);
            if (!v.passed()) {
                return v.refusal();
            }
        }
        Header stamped = request.header().withDestination(a.service().descriptor().name()).withAttachment(a.attachment());
        forwarder.forward(a.service(), new IncomingServiceMessage(stamped));
        return null;
    }
}
