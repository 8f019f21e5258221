package org.ripv.server.clients;

import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.messages.Header;
import org.ripv.messages.Priority;

/**
 * How many of each client's requests wait for their final reply (issue 33 item 10): at most
 * {@link #MAX_WAITING} in all and {@link #MAX_RAISED} at priority or urgent — priority is not a
 * right, and one client's 20,000 urgent requests raised everyone's latency to 17 s and the server's
 * memory to 2.5 GB. A request over the cap is refused at once (the refusal costs less than the
 * request); the count goes down as each final reply goes out, and a client's counts go when it does.
 */
public final class WaitingRequests {
    /** Requests one client may have waiting (the fleet page sends a ?watch per vehicle at once: 1,024 at most). */
    public static final int MAX_WAITING = 2_048;
    /** Of those, at priority or urgent. */
    public static final int MAX_RAISED = 32;

    /** One client's waiting requests by message id (a client may reuse an id: each use counts). */
    private static final class Waiting {
        final Map<Long, Integer> byId = new HashMap<>();
        int all;
        int raised;
    }

    private final Map<String, Waiting> clients = new ConcurrentHashMap<>();

    /** Counts a request in; null when taken, else why not (for the client). */
    public String take(String clientId, Header request) {
        boolean raised = request.priority() != Priority.NORMAL;
        Waiting w = clients.computeIfAbsent(clientId, k -> new Waiting());
        synchronized (w) {
            if (w.all >= MAX_WAITING) {
                return "you have " + w.all + " requests waiting for replies, the most one client may; wait for their replies,"
                        + " then try again";
            }
            if (raised && w.raised >= MAX_RAISED) {
                return "you have " + w.raised + " priority or urgent requests waiting, the most one client may; send this one"
                        + " at normal priority, or wait for their replies";
            }
            w.byId.merge(request.messageId(), 1, Integer::sum);
            w.all++;
            w.raised += raised ? 1 : 0;
            return null;
        }
    }

    /**
     * A final reply to the request went out. A reply to no waiting request (a refusal, a second
     * message about a request already answered) counts nothing.
     */
    public void done(String clientId, Header request) {
        Waiting w = clients.get(clientId);
        if (w == null) {
            return;
        }
        synchronized (w) {
            Integer n = w.byId.get(request.messageId());
            if (n == null) {
                return;
            }
            if (n == 1) {
                w.byId.remove(request.messageId());
            } else {
                w.byId.put(request.messageId(), n - 1);
            }
            w.all--;
            w.raised -= request.priority() != Priority.NORMAL && w.raised > 0 ? 1 : 0;
        }
    }

    /** The client is gone. */
    public void forget(String clientId) {
        clients.remove(clientId);
    }

    /** Requests the client has waiting now. */
    public int waiting(String clientId) {
        Waiting w = clients.get(clientId);
        if (w == null) {
            return 0;
        }
        synchronized (w) {
            return w.all;
        }
    }
}
