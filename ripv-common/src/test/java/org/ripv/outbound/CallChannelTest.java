package org.ripv.outbound;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.ObjectOutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.rmi.RemoteException;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.wire.FrameCodec;

/** The outbound-only connection over real loopback sockets: handshake, calls both ways, and what ends it. */
class CallChannelTest {
    private static final String SECRET = "the service secret";
    private final CountDownLatch never = new CountDownLatch(1);
    private ServerSocket listener;

    @AfterEach
    void close() throws Exception {
        never.countDown();
        if (listener != null) {
            listener.close();
        }
    }

    /** A server and a service side, both past the handshake: {serverSocket, serviceSocket}. */
    private Socket[] pair(String serviceSecret, CompletableFuture<String> serverSaw) throws Exception {
        listener = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        CompletableFuture<Socket> accepted = CompletableFuture.supplyAsync(() -> {
            try {
                Socket s = listener.accept();
                s.setSoTimeout(5000);
                serverSaw.complete(OutboundHandshake.server(new DataInputStream(new BufferedInputStream(s.getInputStream())),
                        new DataOutputStream(new BufferedOutputStream(s.getOutputStream())), SECRET));
                return s;
            } catch (Exception e) {
                serverSaw.completeExceptionally(e);
                return null;
            }
        });
        Socket service = new Socket(InetAddress.getLoopbackAddress(), listener.getLocalPort());
        service.setSoTimeout(5000);
        OutboundHandshake.service(new DataInputStream(new BufferedInputStream(service.getInputStream())),
                new DataOutputStream(new BufferedOutputStream(service.getOutputStream())), serviceSecret, "<Clock>::<nat>");
        return new Socket[] {accepted.get(5, TimeUnit.SECONDS), service};
    }

    @Test
    void callsTravelBothWaysAndExceptionsKeepTheirKind() throws Exception {
        CompletableFuture<String> saw = new CompletableFuture<>();
        Socket[] s = pair(SECRET, saw);
        assertThat(saw.get()).isEqualTo("<Clock>::<nat>");
        Side server = new Side();
        Side service = new Side();
        try (CallChannel atServer = new CallChannel(s[0], "service", server, 1 << 20, Duration.ofSeconds(5));
             CallChannel atService = new CallChannel(s[1], "server", service, 1 << 20, Duration.ofSeconds(5))) {
            ServiceDescriptor d = new ServiceDescriptor("<Clock>::<nat>", "100100", "x", "", List.of()).withRegistration(7);
            assertThat(atService.remote().register(d, null, "")).isEqualTo("token for <Clock>::<nat> 7");
            assertThat(atServer.remote().mailboxes("t")).containsExactly(new MailboxStatus("<Clock>::<nat>TTY1", true, "", false, ""));
            assertThat(atServer.remote().heartbeat("probe")).isTrue();
            assertThat(atServer.remote().withdraw("t", "m", "c", 42L)).isTrue();
            assertThat(service.withdrawn).isEqualTo(42L);
            assertThatThrownBy(() -> atService.remote().console("bad", List.of())).isInstanceOf(SecurityException.class)
                    .hasMessage("unknown session token");
            assertThatThrownBy(() -> atServer.remote().serviceRequest("t", null)).isInstanceOf(UnsupportedOperationException.class);
            assertThatThrownBy(() -> atServer.remote().serviceReplies("t", null)).isInstanceOf(RemoteException.class)
                    .hasMessageContaining("boom");
            assertThat(atServer.remote().toString()).isEqualTo("outbound service");
        }
    }

    @Test
    void aWrongSecretFailsOnBothSidesAndTheSecretIsNeverSent() throws Exception {
        CompletableFuture<String> saw = new CompletableFuture<>();
        assertThatThrownBy(() -> pair("a wrong secret", saw)).isInstanceOf(SecurityException.class)
                .hasMessageContaining("wrong service secret");
        assertThatThrownBy(saw::join).hasCauseInstanceOf(SecurityException.class);
        assertThat(OutboundHandshake.mac(SECRET, "x")).hasSize(64).doesNotContain(SECRET);
    }

    @Test
    void silenceClosesTheConnectionAndFailsTheCallInTime() throws Exception {
        Socket[] s = pair(SECRET, new CompletableFuture<>());
        Side service = new Side();
        try (CallChannel atServer = new CallChannel(s[0], "service", new Side(), 1 << 20, Duration.ofMillis(400));
             CallChannel atService = new CallChannel(s[1], "server", service, 1 << 20, Duration.ofSeconds(5))) {
            long t0 = System.nanoTime();
            assertThatThrownBy(() -> atServer.remote().serviceRequests("hang", List.of())).isInstanceOf(RemoteException.class)
                    .hasMessageContaining("within 400 ms");
            // At least the deadline; without one the call would wait for ever (the peer holds it 5 s+).
            assertThat((System.nanoTime() - t0) / 1_000_000).isBetween(300L, 30_000L);
            assertThat(atServer.isOpen()).isFalse();
            assertThat(atService.closed().get(5, TimeUnit.SECONDS)).isNotEmpty();
            assertThatThrownBy(() -> atServer.remote().heartbeat("x")).isInstanceOf(RemoteException.class).hasMessageContaining("closed");
        }
    }

    @Test
    void aDisallowedObjectOrGarbageEndsTheConnectionNotTheProcess() throws Exception {
        for (boolean garbage : new boolean[] {false, true}) {
            Socket[] s = pair(SECRET, new CompletableFuture<>());
            try (CallChannel atServer = new CallChannel(s[0], "service", new Side(), 1 << 20, Duration.ofSeconds(5))) {
                DataOutputStream out = new DataOutputStream(s[1].getOutputStream());
                if (garbage) {
                    out.writeInt(Integer.MAX_VALUE);
                } else {
                    ByteArrayOutputStream b = new ByteArrayOutputStream();
                    try (ObjectOutputStream o = new ObjectOutputStream(b)) {
                        o.writeObject(new Object[] {1L, "call", "heartbeat", new Object[] {new HashMap<>()}});
                    }
                    FrameCodec.writeRawFrame(out, b.toByteArray());
                }
                out.flush();
                assertThat(atServer.closed().get(5, TimeUnit.SECONDS)).containsAnyOf("frame", "disallowed", "length");
            } finally {
                s[1].close();
                listener.close();
                listener = null;
            }
        }
    }

    /** Both ends' local objects: enough behaviour to see each call arrive. */
    private final class Side implements GenericRMIInterface {
        volatile long withdrawn;

        @Override
        public String challenge(String nonce) {
            throw new UnsupportedOperationException();
        }

        @Override
        public String register(ServiceDescriptor d, GenericRMIInterface s, String secret) {
            return "token for " + d.name() + " " + d.registration();
        }

        @Override
        public void serviceReply(String t, OutgoingServiceMessage r) {
        }

        @Override
        public void serviceReplies(String t, List<OutgoingServiceMessage> r) throws RemoteException {
            throw new RemoteException("boom");
        }

        @Override
        public void console(String t, List<ConsoleEntry> e) {
            throw new SecurityException("unknown session token");
        }

        @Override
        public boolean heartbeat(String t) {
            return true;
        }

        @Override
        public void serviceRequest(String t, IncomingServiceMessage r) {
            throw new UnsupportedOperationException("no");
        }

        @Override
        public void serviceRequests(String t, List<IncomingServiceMessage> r) {
            try {
                never.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public boolean withdraw(String t, String m, String c, long id) {
            withdrawn = id;
            return true;
        }

        @Override
        public List<MailboxStatus> mailboxes(String t) {
            return List.of(new MailboxStatus("<Clock>::<nat>TTY1", true, "", false, ""));
        }
    }
}
