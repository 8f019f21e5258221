package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.rmi.NotBoundException;
import java.rmi.RemoteException;
import java.rmi.registry.LocateRegistry;
import java.rmi.registry.Registry;
import java.rmi.server.UnicastRemoteObject;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.probe.FreePorts;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.security.ServiceProof;
import org.ripv.server.ServerConfig;
import org.ripv.server.security.RegistryGuard;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;

/**
 * Issue 10, item 5: before the fix a local process could {@code rebind} RIPVServer in the
 * registry, and the next service to start handed that process its service secret.
 */
class RegistryTakeoverAttackTest {
    @TempDir
    Path dir;

    static {
        RegistryGuard.install(); // before this JVM's first registry, as the server does
    }

    /** Records every argument it is given; proves nothing. */
    static class Impostor implements GenericRMIInterface {
        final List<String> seen = new CopyOnWriteArrayList<>();
        volatile int challenges;
        volatile int registrations;

        @Override
        public String challenge(String nonce) {
            challenges++;
            seen.add(nonce);
            return ServiceProof.nonce() + " " + "00".repeat(32);
        }

        @Override
        public String register(ServiceDescriptor d, GenericRMIInterface s, String proof) {
            registrations++;
            seen.add(String.valueOf(proof));
            return "ok";
        }

        @Override
        public void serviceReply(String token, OutgoingServiceMessage reply) {
            seen.add(token);
        }

        @Override
        public void serviceReplies(String token, List<OutgoingServiceMessage> replies) {
            seen.add(token);
        }

        @Override
        public void console(String token, List<ConsoleEntry> entries) {
            seen.add(token);
        }

        @Override
        public boolean heartbeat(String token) {
            seen.add(token);
            return true;
        }

        @Override
        public void serviceRequest(String token, IncomingServiceMessage request) {
            seen.add(token);
        }

        @Override
        public void serviceRequests(String token, List<IncomingServiceMessage> requests) {
            seen.add(token);
        }

        @Override
        public boolean withdraw(String token, String mailbox, String clientId, long messageId) {
            return false;
        }

        @Override
        public List<MailboxStatus> mailboxes(String token) {
            return List.of();
        }
    }

    @Test
    void aRebindOfTheServerIsRefusedAndAnUnbindUndone() throws Exception {
        try (TestSystem sys = TestSystem.start(dir.resolve("server"))) {
            Impostor impostor = new Impostor();
            GenericRMIInterface stub = (GenericRMIInterface) UnicastRemoteObject.exportObject(impostor, 0);
            try {
                Registry r = LocateRegistry.getRegistry("localhost", sys.server().registryPort());
                assertThatThrownBy(() -> r.rebind(GenericRMIInterface.BINDING, stub)).as("rebind").isInstanceOf(RemoteException.class);
                assertThatThrownBy(() -> r.bind("Other", stub)).as("bind").isInstanceOf(RemoteException.class);
                sys.register(new ClockService("localhost"));
                assertThat(sys.server().serviceCount()).isEqualTo(1);
                assertThat(impostor.challenges).isZero();

                // unbind carries only a name, which no filter sees: the server binds itself again.
                r.unbind(GenericRMIInterface.BINDING);
                long end = System.nanoTime() + Duration.ofSeconds(10).toNanos();
                while (true) {
                    try {
                        r.lookup(GenericRMIInterface.BINDING);
                        break;
                    } catch (NotBoundException e) {
                        assertThat(System.nanoTime()).as("the server binds itself again").isLessThan(end);
                        Thread.sleep(100);
                    }
                }
            } finally {
                UnicastRemoteObject.unexportObject(impostor, true);
            }
        }
    }

    @Test
    void anImpostorInTheRegistryReceivesNoSecretAndTheServiceKeepsTrying() throws Exception {
        String secret = "0123456789abcdef".repeat(4);
        int port = FreePorts.one();
        // The port squatter: a registry of its own where the server's should be.
        Registry fake = LocateRegistry.createRegistry(port);
        Impostor impostor = new Impostor();
        GenericRMIInterface stub = (GenericRMIInterface) UnicastRemoteObject.exportObject(impostor, 0);
        fake.rebind(GenericRMIInterface.BINDING, stub);
        ClockService clock = new ClockService("localhost");
        ServiceConnector c = ServiceConnector.connect(clock, new ServiceOptions("localhost", port, secret, 0, Duration.ofMillis(300)));
        try {
            long end = System.nanoTime() + Duration.ofSeconds(15).toNanos();
            while (impostor.challenges < 3) {
                assertThat(System.nanoTime()).as("the service keeps trying").isLessThan(end);
                Thread.sleep(100);
            }
            assertThat(impostor.registrations).as("nothing derived from the secret was sent").isZero();
            assertThat(impostor.seen).allSatisfy(arg -> assertThat(arg).doesNotContain(secret));
            assertThat(c.isRegistered()).isFalse();

            // The real server comes back on that port (with that secret): the service registers.
            UnicastRemoteObject.unexportObject(impostor, true);
            UnicastRemoteObject.unexportObject(fake, true);
            Path data = dir.resolve("real");
            Files.createDirectories(data);
            Files.writeString(data.resolve("service.secret"), secret + "\n");
            try (TestSystem sys = TestSystem.start(ServerConfig.forTests(data).withPorts(0, port, -1))) {
                assertThat(c.awaitRegistered(Duration.ofSeconds(20))).as("registered with the real server").isTrue();
                assertThat(sys.server().serviceCount()).isEqualTo(1);
            }
        } finally {
            c.close();
            clock.stop();
        }
    }
}
