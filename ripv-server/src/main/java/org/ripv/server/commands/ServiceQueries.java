package org.ripv.server.commands;

import java.time.Duration;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.Executor;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import java.util.function.Supplier;
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
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.requests.ServerReplies;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceLiveness;
import org.ripv.server.services.ServiceRegistry;
import org.ripv.server.session.ConsoleCommands;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.session.Rights;

/**
 * The server commands that ask services: {@code ?mailboxes} asks every service at once, each
 * with its own deadline, and lists a slow one as not answering instead of waiting for it;
 * {@code ?status} asks one with the same deadline; {@code ?services} lists the registered
 * services with their health as the last call or check found it, and those recently lost. None
 * holds a thread while it waits: the reply is composed when the last answer or deadline comes.
 */
public final class ServiceQueries {
    private final ServiceRegistry services;
    private final ServiceLiveness liveness;
    private final Executor checkers;
    private final Supplier<PermitFile> permits;
    private final Map<String, OperatorLock> locks;
    private final ConsoleHub console;
    private final Consumer<OutgoingServerMessage> outbox;
    private final Duration deadline;

    /**
     * @param checkers where the calls to services run
     * @param locks    the operator locks, shown beside each MailBox
     * @param console  the vehicles' call state, shown beside each MailBox
     * @param outbox   where the replies go (the Post Office's outbox)
     */
    public ServiceQueries(ServiceRegistry services, ServiceLiveness liveness, Executor checkers, Supplier<PermitFile> permits,
                          Map<String, OperatorLock> locks, ConsoleHub console, Consumer<OutgoingServerMessage> outbox) {
        this.services = services;
        this.liveness = liveness;
        this.checkers = checkers;
        this.permits = permits;
        this.locks = locks;
        this.console = console;
        this.outbox = outbox;
        this.deadline = ServiceLiveness.QUERY_DEADLINE;
    }

    /** One service's answer: its MailBoxes, or why there are none. */
    private record Answer(ServiceReference ref, List<MailboxStatus> boxes, String failure) {}

    /** Asks every registered service for its MailBoxes, each with the deadline; completes when all have answered or failed. */
    private List<CompletableFuture<Answer>> askAll() {
        List<CompletableFuture<Answer>> asks = new ArrayList<>();
        for (ServiceReference ref : services.all()) {
            asks.add(ref.mailboxes(checkers, deadline)
                    .handle((boxes, e) -> new Answer(ref, boxes, e == null ? null : failure(ref, e))));
        }
        return asks;
    }

    /** The MailBoxes the services list now, and the services that did not answer in time. */
    public record Known(List<String> addresses, List<String> notAnswering) {}

    /** {@link Known}, to resolve vehicle names ({@link org.ripv.server.vehicles.VehicleNames}); never fails. */
    public CompletableFuture<Known> known() {
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

    public void mailboxes(IncomingServerMessage request) {
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
                    MailboxStatus withLock = readable(request, withLock(s));
                    all.add(withLock);
                    text.append(describe(withLock)).append('\n');
                }
            }
            outbox.accept(request.reply(Footer.ok(Ids.FID_MAILBOXES, all.size() + " mailbox(es)\n" + text.toString().stripTrailing(),
                    new MailboxList(all)).via(ServerReplies.SERVICE)));
        });
    }

    /**
     * What a user sees of a MailBox: everything with the read right ({@code ?read}), else its
     * address only — a vehicle's state, last position, lock and running workflow are as private as
     * its console (issue 23, item 11).
     */
    private MailboxStatus readable(IncomingServerMessage request, MailboxStatus s) {
        if (Rights.mayRead(permits.get(), request.header().origin().user(), s.address())) {
            return s;
        }
        return new MailboxStatus(s.address(), false, HIDDEN, false, "", null, "");
    }

    /** The detail shown instead of a MailBox's state to a user without the read right. */
    static final String HIDDEN = "state hidden: reading this MailBox needs the ?read right (docs/permit.md)";

    public void status(IncomingServerMessage request, MailboxAddress address) {
        String why = Rights.whyNotRead(permits.get(), request.header().origin().user(), address.toString());
        if (why != null) {
            outbox.accept(ServerReplies.error(request, Ids.FID_STATUS, ErrorCode.FORBIDDEN, why));
            return;
        }
        ServiceReference ref = services.find(address.service().toString()).orElse(null);
        if (ref == null) {
            outbox.accept(ServerReplies.error(request, Ids.FID_STATUS, ErrorCode.UNKNOWN_SERVICE,
                    "no service " + address.service() + " is registered"));
            return;
        }
        ref.mailboxes(checkers, deadline).whenComplete((boxes, e) -> {
            if (e != null) {
                outbox.accept(ServerReplies.error(request, Ids.FID_STATUS, ErrorCode.SERVICE_GONE,
                        address.service() + " is " + failure(ref, e)));
                return;
            }
            for (MailboxStatus s : boxes) {
                if (s.address().equals(address.toString())) {
                    MailboxStatus withLock = withLock(s);
                    outbox.accept(request.reply(Footer.ok(Ids.FID_STATUS, describe(withLock), withLock)
                            .via(ServerReplies.SERVICE)));
                    return;
                }
            }
            outbox.accept(ServerReplies.error(request, Ids.FID_STATUS, ErrorCode.UNKNOWN_MAILBOX,
                    "no MailBox " + address + " at " + address.service() + "; ?mailboxes lists them"));
        });
    }

    /** {@code ?services}: no calls, only what calls and checks have found. */
    public OutgoingServerMessage services(IncomingServerMessage request) {
        List<ServiceReference> refs = services.all();
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
        for (Map.Entry<String, ServiceLiveness.Lost> e : liveness.lost().entrySet()) {
            if (services.find(e.getKey()).isEmpty()) {
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


    /** Current MailBox status with the operator lock and the vehicle's call state added. */
    private MailboxStatus withLock(MailboxStatus s) {
        OperatorLock l = locks.get(s.address());
        MailboxStatus withState = s.withSession(console.state(s.address()));
        return l == null || l.expired() ? withState : withState.withLock(l.user());
    }

    /** One line of {@code ?mailboxes} and the text of {@code ?status}. */
    static String describe(MailboxStatus s) {
        if (HIDDEN.equals(s.detail())) {
            return s.address() + ": " + s.detail();
        }
        String what = !s.running().isEmpty() ? "busy: " + s.running()
                : (s.available() ? "available" : "not available") + (s.busy() ? ", busy" : "");
        return s.address() + ": " + what
                + (s.lockedBy().isEmpty() ? "" : ", locked by " + s.lockedBy())
                + (s.detail().isEmpty() ? "" : " (" + s.detail() + ")")
                + (s.session() == null ? "" : "; vehicle " + ConsoleCommands.describeState(s.session()));
    }
}
