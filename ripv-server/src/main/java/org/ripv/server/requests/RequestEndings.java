package org.ripv.server.requests;

import java.net.NoRouteToHostException;
import java.net.SocketTimeoutException;
import java.rmi.ConnectException;
import java.rmi.NoSuchObjectException;
import java.rmi.RemoteException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.Consumer;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.server.services.ServiceReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * How a forwarded request ends when its service does not answer it, and what the client is told:
 * never delivered ({@code SERVICE_GONE}, "could not reach … at ADDRESS", at once and truthfully),
 * delivered but silent ({@code TIMEOUT}, withdrawn if it had not started), or lost with its
 * service ({@code SERVICE_GONE}, "went away"). Nothing here waits for another request's call.
 */
public record RequestEndings(Consumer<OutgoingServerMessage> reply, PendingRequests pending, Executor withdrawals,
                             Duration timeout) {
    private static final Logger log = LoggerFactory.getLogger(RequestEndings.class);

    private void error(Header h, String sid, ErrorCode code, String text) {
        reply.accept(new IncomingServerMessage(h).reply(Footer.error(sid, code, text).via(ServerReplies.SERVICE)));
    }

    /** A request whose call to its service failed. */
    public void undeliverable(ServiceReference ref, IncomingServiceMessage r, Exception e) {
        String why = ServiceReference.why(e, ref.address());
        log.warn("could not reach {} at {}: {}", ref, ref.address(), why);
        if (pending.complete(r.header(), ref.descriptor().name()) != null) {
            error(r.header(), ref.descriptor().sid(), ErrorCode.SERVICE_GONE, "could not reach " + ref.descriptor().name() + " at "
                    + ref.address() + ": " + why + "; '" + Header.abbreviate(r.header().body())
                    + (neverConnected(e) ? "' was not delivered and will not run" : "' was probably not delivered")
                    + " (the server gives up on a call after its RMI deadlines)");
        }
    }

    /** True when a call failed before any byte of it could leave (no connection): it surely did not arrive. */
    static boolean neverConnected(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause() == t ? null : t.getCause()) {
            if (t instanceof ConnectException || t instanceof java.net.ConnectException
                    || t instanceof SocketTimeoutException && String.valueOf(t.getMessage()).startsWith("could not reach")
                    || t instanceof NoSuchObjectException || t instanceof NoRouteToHostException) {
                return true;
            }
        }
        return e.getMessage() != null && e.getMessage().contains("no longer registered");
    }

    /**
     * A request heard nothing for the timeout. Never delivered: say so (SERVICE_GONE), at once.
     * Delivered: try to withdraw it, on a thread of its own with the RMI deadlines, so that no
     * other request waits on this call; skip that when the service is known not to answer.
     */
    public void timedOut(PendingRequests.Pending p, ServiceReference ref) {
        String what = "'" + Header.abbreviate(p.header().body()) + "'";
        if (ref != null && (ref.unqueue(p.header()) || ref.undelivered(p.header()))) {
            error(p.header(), ref.descriptor().sid(), ErrorCode.SERVICE_GONE, "could not reach " + p.service() + " at "
                    + ref.address() + ": timed out; " + what + " was not delivered and will not run");
            return;
        }
        String sid = ref == null ? Ids.FID_NONE : ref.descriptor().sid();
        String silent = p.service() + " did not answer " + what + " within " + timeout.toSeconds()
                + " s; it was delivered and may still complete on the device";
        try {
            withdrawals.execute(() -> {
                boolean withdrawn = false;
                try {
                    withdrawn = ref != null && ref.problem().isEmpty() && ref.withdraw(p.header());
                } catch (RemoteException | RuntimeException e) {
                    log.debug("could not withdraw #{}: {}", p.header().messageId(), e.toString());
                }
                error(p.header(), sid, ErrorCode.TIMEOUT, withdrawn ? p.service() + " did not start " + what + " within "
                        + timeout.toSeconds() + " s (its MailBox was busy); it was withdrawn and will not run" : silent);
            });
        } catch (RejectedExecutionException e) {
            error(p.header(), sid, ErrorCode.TIMEOUT, silent); // many withdrawals under way (or stopping): answer without one
        }
    }

    /** A service left (dropped, or registered again): its pending requests end now, each told why. */
    public void drop(ServiceReference ref, String why) {
        List<PendingRequests.Pending> failed = pending.failService(ref.descriptor().name());
        ref.close();
        for (PendingRequests.Pending p : failed) {
            String what = "'" + Header.abbreviate(p.header().body()) + "'";
            String text = ref.undelivered(p.header()) && !ref.problem().isEmpty()
                    ? "could not reach " + ref.descriptor().name() + " at " + ref.address() + ": " + ref.problem()
                            .replace("could not reach " + ref.address() + ": ", "") + "; " + what + " was not delivered"
                    : ref.descriptor().name() + " " + why + " before answering " + what;
            error(p.header(), ref.descriptor().sid(), ErrorCode.SERVICE_GONE, text);
        }
    }
}
