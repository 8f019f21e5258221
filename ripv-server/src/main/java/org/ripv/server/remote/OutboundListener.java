package org.ripv.server.remote;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.rmi.RemoteException;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Semaphore;
import java.util.function.BiConsumer;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.naming.ServiceName;
import org.ripv.outbound.CallChannel;
import org.ripv.outbound.OutboundHandshake;
import org.ripv.outbound.OutboundLimits;
import org.ripv.rmi.DeadlineSocketFactory;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.server.services.ServiceAdmission;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceRegistry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server's port for services in outbound-only mode ({@code --outbound-only}): a service
 * behind NAT or a firewall connects here, both prove the service secret by HMAC, and the
 * server's calls to it travel back over that connection through a {@link CallChannel} proxy —
 * the rest of the server sees an ordinary {@link GenericRMIInterface} stub. Registration over it
 * goes through the same {@link ServiceAdmission} as over RMI. When the connection ends, the
 * service is dropped at once (its pending requests fail) and may connect again.
 */
public final class OutboundListener implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(OutboundListener.class);
    /** Handshakes under way at once: a flood of idle connections cannot tie up more. */
    private static final int MAX_HANDSHAKES = 32;

    private final String secret;
    private final ServiceRegistry services;
    private final ServiceAdmission admission;
    private final BiConsumer<ServiceReference, String> drop;
    private final GenericRMIInterface remote;
    private final ServerSocket listener;
    private final Semaphore handshakes = new Semaphore(MAX_HANDSHAKES);
    private final Set<CallChannel> channels = ConcurrentHashMap.newKeySet();
    private volatile boolean open = true;

    /**
     * @param secret the service secret both ends prove they know
     * @param drop   told of a service whose outbound connection ended (its pending requests fail)
     * @param remote the server's side of the interface, which the service calls
     */
    public OutboundListener(String secret, ServiceRegistry services, ServiceAdmission admission,
                            BiConsumer<ServiceReference, String> drop, GenericRMIInterface remote, InetAddress bind, int port)
            throws IOException {
        this.secret = secret;
        this.services = services;
        this.admission = admission;
        this.drop = drop;
        this.remote = remote;
        ServerSocket s = new ServerSocket();
        s.setReuseAddress(true);
        try {
            s.bind(new InetSocketAddress(bind, port), 50);
        } catch (IOException e) {
            s.close();
            throw new IOException("cannot listen for outbound-only services on port " + port + " (in use?): " + e.getMessage(), e);
        }
        this.listener = s;
        Thread t = new Thread(this::acceptLoop, "ripv-outbound-acceptor");
        t.setDaemon(true);
        t.start();
    }

    public int port() {
        return listener.getLocalPort();
    }

    private void acceptLoop() {
        while (open) {
            Socket s;
            try {
                s = listener.accept();
            } catch (IOException e) {
                if (open) {
                    log.warn("outbound accept failed: {}", e.toString());
                }
                continue;
            }
            if (!handshakes.tryAcquire()) {
                log.warn("refusing outbound connection from {}: {} handshakes under way", s.getRemoteSocketAddress(), MAX_HANDSHAKES);
                closeQuietly(s);
                continue;
            }
            Thread t = new Thread(() -> {
                try {
                    handshake(s);
                } finally {
                    handshakes.release();
                }
            }, "ripv-outbound-handshake");
            t.setDaemon(true);
            t.start();
        }
    }

    private void handshake(Socket s) {
        String peer = s.getInetAddress().getHostAddress() + ":" + s.getPort();
        try {
            s.setSoTimeout(OutboundLimits.HANDSHAKE_MILLIS);
            DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream()));
            DataOutputStream out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
            String name = OutboundHandshake.server(in, out, secret);
            ServiceName.parse(name);
            int deadline = DeadlineSocketFactory.fromSystem().readMillis();
            Side side = new Side(name);
            CallChannel c = new CallChannel(s, peer, side, OutboundLimits.MAX_FRAME, Duration.ofMillis(Math.max(deadline, 5_000)));
            side.channel = c;
            channels.add(c);
            c.closed().thenAccept(why -> {
                channels.remove(c);
                ServiceReference ref = services.find(name).orElse(null);
                if (ref != null && ref.stub() == c.remote() && services.remove(ref)) {
                    log.warn("{}: its outbound connection from {} closed ({})", ref, peer, why);
                    drop.accept(ref, "closed its outbound connection (" + why + ")");
                }
            });
            log.info("outbound connection from {} for {}", peer, name);
        } catch (SecurityException e) {
            log.warn("refused an outbound connection from {}: {}", peer, e.getMessage());
            closeQuietly(s);
        } catch (IOException | RuntimeException e) {
            log.info("dropped an outbound connection from {}: {}", peer, e.toString());
            closeQuietly(s);
        }
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }

    @Override
    public void close() {
        open = false;
        try {
            listener.close();
        } catch (IOException ignored) {
            // closing anyway
        }
        channels.forEach(CallChannel::close);
    }

    /**
     * What an outbound service may call: the server's side of the interface, with registration
     * proven by the handshake (the secret is not sent again) and bound to the proven name.
     */
    private final class Side implements GenericRMIInterface {
        private final String name;
        private volatile CallChannel channel;

        Side(String name) {
            this.name = name;
        }

        @Override
        public String challenge(String serviceNonce) {
            throw new UnsupportedOperationException("an outbound connection proved the secret in its handshake");
        }

        @Override
        public String register(ServiceDescriptor d, GenericRMIInterface ignored, String notSent) {
            if (d == null || !d.name().equals(name)) {
                throw new SecurityException("this connection proved the secret for " + name + ", not for "
                        + (d == null ? "nothing" : d.name()));
            }
            return admission.admit(d, channel.remote());
        }

        @Override
        public void serviceReply(String token, OutgoingServiceMessage reply) throws RemoteException {
            remote.serviceReply(token, reply);
        }

        @Override
        public void serviceReplies(String token, List<OutgoingServiceMessage> replies) throws RemoteException {
            remote.serviceReplies(token, replies);
        }

        @Override
        public void console(String token, List<ConsoleEntry> entries) throws RemoteException {
            remote.console(token, entries);
        }

        @Override
        public boolean heartbeat(String token) throws RemoteException {
            return remote.heartbeat(token);
        }

        // What the server does not take from any service, it does not take over this connection either.
        @Override
        public void serviceRequest(String token, IncomingServiceMessage request) throws RemoteException {
            remote.serviceRequest(token, request);
        }

        @Override
        public void serviceRequests(String token, List<IncomingServiceMessage> requests) throws RemoteException {
            remote.serviceRequests(token, requests);
        }

        @Override
        public boolean withdraw(String token, String mailbox, String clientId, long messageId) throws RemoteException {
            return remote.withdraw(token, mailbox, clientId, messageId);
        }

        @Override
        public List<MailboxStatus> mailboxes(String token) throws RemoteException {
            return remote.mailboxes(token);
        }
    }
}
