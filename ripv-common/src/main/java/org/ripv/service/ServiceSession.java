package org.ripv.service;

import java.rmi.RemoteException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.rmi.GenericRMIInterface;

/**
 * What a {@link ServiceConnector} holds while it is registered: the server in use and the session
 * token, shared by the connector (which sets them), the service's remote side ({@link ServiceRemote},
 * which checks the server's token) and the reply path ({@link #sink}).
 */
final class ServiceSession {
    private volatile GenericRMIInterface server;
    private volatile String token;
    private volatile CountDownLatch registered = new CountDownLatch(1);
    /** Guards the window in which the server knows the new token and this side does not yet. */
    private final Object tokenLock = new Object();
    private boolean registering;

    String token() {
        return token;
    }

    GenericRMIInterface server() {
        return server;
    }

    boolean isRegistered() {
        return token != null;
    }

    boolean awaitRegistered(Duration timeout) throws InterruptedException {
        return registered.await(timeout.toMillis(), TimeUnit.MILLISECONDS);
    }

    /** A registration call is about to go out: the server may call back before it returns. */
    void registering() {
        synchronized (tokenLock) {
            registering = true;
        }
    }

    /**
     * The registration call returned: with {@code t} (the token) the session is open, with null
     * it failed. One step with the token: a server call waiting in {@link #check} must never see
     * the registration over and the token not yet set (it was refused as "unknown").
     */
    void registered(GenericRMIInterface s, String t) {
        synchronized (tokenLock) {
            if (t != null) {
                server = s;
                token = t;
            }
            registering = false;
            tokenLock.notifyAll();
        }
        if (t != null) {
            registered.countDown();
        }
    }

    /** The server no longer knows this service. */
    void lost() {
        token = null;
        if (registered.getCount() == 0) {
            registered = new CountDownLatch(1);
        }
    }

    /** Refuses a call whose token is not this session's; waits out a registration still under way. */
    void check(String t) throws RemoteException {
        synchronized (tokenLock) {
            // The server may call as soon as it has registered us, before register() returned here.
            long end = System.nanoTime() + 5_000_000_000L;
            while (registering && (token == null || !token.equals(t)) && System.nanoTime() < end) {
                try {
                    tokenLock.wait(100);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    break;
                }
            }
            if (token == null || !token.equals(t)) {
                throw new RemoteException("unknown session token: register first");
            }
        }
    }

    /** Asks the server in use for another registered service's stub (null: not reachable directly). */
    GenericRMIInterface peer(String service) throws RemoteException {
        GenericRMIInterface s = server;
        String t = token;
        if (s == null || t == null) {
            throw new RemoteException("not registered with a server");
        }
        return s.peer(t, service);
    }

    /** Where the service's replies go: to the server in use, over RMI. */
    ReplySink sink() {
        return new Sink();
    }

    private final class Sink implements ReplySink {
        @Override
        public void reply(OutgoingServiceMessage reply) throws Exception {
            server().serviceReply(token(), reply);
        }

        @Override
        public void replies(List<OutgoingServiceMessage> replies) throws Exception {
            server().serviceReplies(token(), replies);
        }

        @Override
        public void console(List<ConsoleEntry> entries) throws Exception {
            server().console(token(), entries);
        }

        /** The server calls {@code more} when a page went out to the client's socket. */
        @Override
        public boolean pacesPages() {
            return true;
        }

        private GenericRMIInterface server() throws RemoteException {
            GenericRMIInterface s = server;
            if (s == null || token == null) {
                throw new RemoteException("not registered with a server");
            }
            return s;
        }

        private String token() throws RemoteException {
            String t = token;
            if (t == null) {
                throw new RemoteException("not registered with a server");
            }
            return t;
        }
    }
}
