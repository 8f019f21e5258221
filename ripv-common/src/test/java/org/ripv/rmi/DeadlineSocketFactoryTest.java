package org.ripv.rmi;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.InvalidClassException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.wire.WireFilter;

class DeadlineSocketFactoryTest {

    static Object roundTrip(Object o, WireFilter filter) throws Exception {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(b)) {
            out.writeObject(o);
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(b.toByteArray()))) {
            in.setObjectInputFilter(filter);
            return in.readObject();
        }
    }

    /**
     * A listener whose accept queue is full drops further SYNs (Linux): a connect to it hangs the
     * way one to a host behind a dropping firewall does, and the factory must give up in time.
     */
    @Test
    void aConnectToAHostThatDropsPacketsFailsWithinTheDeadline() throws Exception {
        List<Socket> fill = new ArrayList<>();
        try (ServerSocket full = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            DeadlineSocketFactory f = new DeadlineSocketFactory(400, 1000);
            boolean hung = false;
            for (int i = 0; i < 8 && !hung; i++) {
                long t0 = System.nanoTime();
                try {
                    fill.add(f.createSocket("127.0.0.1", full.getLocalPort()));
                } catch (SocketTimeoutException e) {
                    long ms = (System.nanoTime() - t0) / 1_000_000;
                    // At least the deadline; the upper bound only tells it from the kernel's own ~2 min.
                    assertThat(ms).isBetween(300L, 30_000L);
                    assertThat(e.getMessage()).contains("could not reach 127.0.0.1:" + full.getLocalPort()).contains("timed out");
                    hung = true;
                }
            }
            assertThat(hung).as("the kernel kept accepting; the test needs a dropping listener").isTrue();
        } finally {
            for (Socket s : fill) {
                s.close();
            }
        }
    }

    @Test
    void aReadWaitsNoLongerThanTheReadDeadline() throws Exception {
        try (ServerSocket silent = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
             Socket s = new DeadlineSocketFactory(1000, 300).createSocket("127.0.0.1", silent.getLocalPort());
             Socket peer = silent.accept()) {
            InputStream in = s.getInputStream();
            long t0 = System.nanoTime();
            assertThatThrownBy(in::read).isInstanceOf(SocketTimeoutException.class);
            assertThat((System.nanoTime() - t0) / 1_000_000).as("at least the deadline; without one the read never ends")
                    .isBetween(200L, 30_000L);
            assertThat(peer.isConnected()).isTrue();
        }
    }

    @Test
    void theCallerMayLowerTheDeadlinesButNotRaiseThem() throws Exception {
        System.setProperty(DeadlineSocketFactory.READ_PROPERTY, "200");
        try (ServerSocket silent = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
             Socket s = new DeadlineSocketFactory(1000, 60_000).createSocket("127.0.0.1", silent.getLocalPort())) {
            assertThat(s.getSoTimeout()).isEqualTo(200);
        } finally {
            System.clearProperty(DeadlineSocketFactory.READ_PROPERTY);
        }
        assertThatThrownBy(() -> new DeadlineSocketFactory(0, 1)).isInstanceOf(IllegalArgumentException.class);
    }

    /** The stub a RIPV process hands out carries the factory, and the RMI filters let exactly it through. */
    @Test
    void exportedStubsCarryTheFactoryThroughTheRmiFilters() throws Exception {
        GenericRMIInterface obj = new Probe();
        GenericRMIInterface stub = RmiSupport.export(obj, 0);
        try {
            assertThat(stub.toString()).contains("DeadlineSocketFactory");
            assertThat(roundTrip(stub, WireFilter.forRmi(1 << 20))).isInstanceOf(GenericRMIInterface.class);
            assertThat(roundTrip(stub, WireFilter.forProcess(1 << 20))).isInstanceOf(GenericRMIInterface.class);
            assertThat(((GenericRMIInterface) roundTrip(stub, WireFilter.forRmi(1 << 20))).heartbeat("x")).isTrue();
            // Another socket factory, or the factory on the client socket, stays out.
            assertThatThrownBy(() -> roundTrip(new javax.rmi.ssl.SslRMIClientSocketFactory(), WireFilter.forRmi(1 << 20)))
                    .isInstanceOf(InvalidClassException.class);
            assertThatThrownBy(() -> roundTrip(new DeadlineSocketFactory(1, 1), WireFilter.forFrames(1 << 20)))
                    .isInstanceOf(InvalidClassException.class);
        } finally {
            RmiSupport.unexport(obj);
        }
    }

    /** Answers heartbeats only. */
    static class Probe implements GenericRMIInterface {
        @Override public String challenge(String n) { throw new UnsupportedOperationException(); }
        @Override public String register(org.ripv.messages.ServiceDescriptor d, GenericRMIInterface s, String secret) { throw new UnsupportedOperationException(); }
        @Override public void serviceReply(String t, org.ripv.messages.OutgoingServiceMessage r) { throw new UnsupportedOperationException(); }
        @Override public void serviceReplies(String t, List<org.ripv.messages.OutgoingServiceMessage> r) { throw new UnsupportedOperationException(); }
        @Override public void console(String t, List<org.ripv.messages.ConsoleEntry> e) { throw new UnsupportedOperationException(); }
        @Override public boolean heartbeat(String t) { return true; }
        @Override public void serviceRequest(String t, org.ripv.messages.IncomingServiceMessage r) { throw new UnsupportedOperationException(); }
        @Override public void serviceRequests(String t, List<org.ripv.messages.IncomingServiceMessage> r) { throw new UnsupportedOperationException(); }
        @Override public boolean withdraw(String t, String m, String c, long id) { throw new UnsupportedOperationException(); }
        @Override public List<org.ripv.messages.MailboxStatus> mailboxes(String t) { throw new UnsupportedOperationException(); }
    }
}
