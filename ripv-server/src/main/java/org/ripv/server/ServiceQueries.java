package org.ripv.server;

import java.time.Duration;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.TimeoutException;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.requests.ServerReplies;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceLiveness;

/**
 * The server commands that ask services: {@code ?mailboxes} asks every service at once, each
 * with its own deadline, and lists a slow one as not answering instead of waiting for it;
 * {@code ?status} asks one with the same deadline; {@code ?services} lists the registered
 * services with their health as the last call or check found it, and those recently lost. None
 * holds a thread while it waits: the reply is composed when the last answer or deadline comes.
 */
final class ServiceQueries {
    private final RIPVServer server;
    private final Duration deadline;

    ServiceQueries(RIPVServer server) {
        this(server, ServiceLiveness.QUERY_DEADLINE);
    }

    ServiceQueries(RIPVServer server, Duration deadline) {
        this.server = server;
        this.deadline = deadline;
    }

    /** One service's answer: its MailBoxes, or why there are none. */
    private record Answer(ServiceReference ref, List<MailboxStatus> boxes, String failure) {}

    /** Asks every registered service for its MailBoxes, each with the deadline; completes when all have answered or failed. */
    private List<CompletableFuture<Answer>> askAll() {
        List<CompletableFuture<Answer>> asks = new ArrayList<>();
        for (ServiceReference ref : server.services()) {
            asks.add(ref.mailboxes(server.checkers(), deadline)
                    .handle((boxes, e) -> new Answer(ref, boxes, e == null ? null : failure(ref, e))));
        }
        return asks;
    }

    /** The MailBoxes the services list now, and the services that did not answer in time. */
    record Known(List<String> addresses, List<String> notAnswering) {}

    /** {@link Known}, to resolve vehicle names ({@link org.ripv.server.vehicles.VehicleNames}); never fails. */
    CompletableFuture<Known> known() {
        List<CompletableFuture<Answer>> asks = askAll();
        return CompletableFuture.allOf(asks.toArray(CompletableFuture[]::new)).handle((v, e) -> {
            List<String> addresses = new ArrayList<>();
            List<String> silent = new ArrayList<>();
            for (CompletableFuture<Answer> f : asks) {
                Answer a = f.join();
                if (a.failure() != null) {
                    silent.add(a.ref().descriptor().name());
                } else {
                    a.boxes().forEach(s -> addresses.add(s.address()));
                }
            }
            return new Known(addresses, silent);
        });
    }

    void mailboxes(IncomingServerMessage request) {
        List<CompletableFuture<Answer>> asks = askAll();
        CompletableFuture.allOf(asks.toArray(CompletableFuture[]::new)).whenComplete((v, e) -> {
            List<MailboxStatus> all = new ArrayList<>();
            StringBuilder text = new StringBuilder();
            for (CompletableFuture<Answer> f : asks) {
                Answer a = f.join();
                if (a.failure() != null) {
                    text.append(a.ref().descriptor().name()).append(": ").append(a.failure()).append('\n');
                    continue;
                }
                for (MailboxStatus s : a.boxes()) {
                    MailboxStatus withLock = readable(request, server.withLock(s));
                    all.add(withLock);
                    text.append(ServerCommands.describe(withLock)).append('\n');
                }
            }
            server.reply(request.reply(Footer.ok(Ids.FID_MAILBOXES, all.size() + " mailbox(es)\n" + text.toString().stripTrailing(),
                    new MailboxList(all)).via(ServerReplies.SERVICE)));
        });
    }

    /**
     * What a user sees of a MailBox: everything with the read right ({@code ?read}), else its
     * address only — a vehicle's state, last position, lock and running workflow are as private as
     * its console (issue 23, item 11).
     */
    private MailboxStatus readable(IncomingServerMessage request, MailboxStatus s) {
        if (org.ripv.server.session.Rights.mayRead(server.permits(), request.header().origin().user(), s.address())) {
            return s;
        }
        return new MailboxStatus(s.address(), false, HIDDEN, false, "", null, "");
    }

    /** The detail shown instead of a MailBox's state to a user without the read right. */
    static final String HIDDEN = "state hidden: reading this MailBox needs the ?read right (docs/permit.md)";

    void status(IncomingServerMessage request, MailboxAddress address) {
        String why = org.ripv.server.session.Rights.whyNotRead(server.permits(), request.header().origin().user(), address.toString());
        if (why != null) {
            server.reply(ServerTaskManager.error(request, Ids.FID_STATUS, ErrorCode.FORBIDDEN, why));
            return;
        }
        ServiceReference ref = server.service(address.service().toString()).orElse(null);
        if (ref == null) {
            server.reply(ServerTaskManager.error(request, Ids.FID_STATUS, ErrorCode.UNKNOWN_SERVICE,
                    "no service " + address.service() + " is registered"));
            return;
        }
        ref.mailboxes(server.checkers(), deadline).whenComplete((boxes, e) -> {
            if (e != null) {
                server.reply(ServerTaskManager.error(request, Ids.FID_STATUS, ErrorCode.SERVICE_GONE,
                        address.service() + " is " + failure(ref, e)));
                return;
            }
            for (MailboxStatus s : boxes) {
                if (s.address().equals(address.toString())) {
                    MailboxStatus withLock = server.withLock(s);
                    server.reply(request.reply(Footer.ok(Ids.FID_STATUS, ServerCommands.describe(withLock), withLock)
                            .via(ServerReplies.SERVICE)));
                    return;
                }
            }
            server.reply(ServerTaskManager.error(request, Ids.FID_STATUS, ErrorCode.UNKNOWN_MAILBOX,
                    "no MailBox " + address + " at " + address.service() + "; ?mailboxes lists them"));
        });
    }

    /** {@code ?services}: no calls, only what calls and checks have found. */
    OutgoingServerMessage services(IncomingServerMessage request) {
        List<ServiceReference> refs = server.services();
        List<ServiceDescriptor> list = refs.stream().map(ServiceReference::descriptor).toList();
        StringBuilder b = new StringBuilder(list.size() + " service(s) registered");
        for (ServiceReference r : refs) {
            ServiceDescriptor d = r.descriptor();
            b.append('\n').append(d.name()).append("  SID ").append(d.sid())
                    .append(d.description().isEmpty() ? "" : "  " + d.description());
            String problem = r.problem();
            if (!problem.isEmpty()) {
                b.append("\n    NOT ANSWERING since ").append(r.problemSince()).append(": ").append(problem);
            }
        }
        for (Map.Entry<String, ServiceLiveness.Lost> e : server.liveness().lost().entrySet()) {
            if (server.service(e.getKey()).isEmpty()) {
                ServiceLiveness.Lost l = e.getValue();
                b.append('\n').append(e.getKey()).append(l.refused() ? "  REFUSED at " : "  LOST at ").append(l.when()).append(": ")
                        .append(l.why()).append(l.refused() ? " (its registration; it keeps trying)" : " (removed until it registers again)");
            }
        }
        return request.reply(Footer.ok(Ids.FID_SERVICES, b.toString(), new ServiceList(list)).via(ServerReplies.SERVICE));
    }

    private String failure(ServiceReference ref, Throwable e) {
        Throwable t = e instanceof CompletionException && e.getCause() != null ? e.getCause() : e;
        if (t instanceof TimeoutException) {
            ref.trouble("no answer from " + ref.address() + " within " + deadline.toMillis() + " ms");
            return "not answering (no answer within " + deadline.toMillis() + " ms from " + ref.address() + ")";
        }
        return "not answering (" + ServiceReference.why(t, ref.address()) + " at " + ref.address() + ")";
    }

}
