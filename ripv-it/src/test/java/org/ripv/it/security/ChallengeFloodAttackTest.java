package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.rmi.registry.LocateRegistry;
import java.rmi.registry.Registry;
import java.rmi.server.UnicastRemoteObject;
import java.time.Duration;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.probe.FreePorts;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.security.ServiceProof;
import org.ripv.server.security.RegistryGuard;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * Issue 23, item 1: anyone who reaches the registry could call {@code challenge()} without limit;
 * the server kept the newest 256, so a flood pushed a starting service's challenge out, the server
 * answered "unknown, used or expired; register again", and the service process exited.
 */
@ResourceLock(Shared.CPU)
class ChallengeFloodAttackTest {
    @TempDir
    Path dir;

    static {
        RegistryGuard.install();
    }

    @Test
    void aServiceProcessRegistersAndStaysWhileAnotherProcessFloodsChallenges() throws Exception {
        try (TestSystem sys = TestSystem.start(dir.resolve("server"))) {
            AtomicBoolean flooding = new AtomicBoolean(true);
            AtomicLong sent = new AtomicLong();
            ExecutorService flood = Executors.newFixedThreadPool(4);
            for (int i = 0; i < 4; i++) {
                flood.execute(() -> {
                    try {
                        GenericRMIInterface server = (GenericRMIInterface) LocateRegistry
                                .getRegistry("localhost", sys.server().registryPort()).lookup(GenericRMIInterface.BINDING);
                        while (flooding.get()) {
                            server.challenge(ServiceProof.nonce());
                            sent.incrementAndGet();
                        }
                    } catch (Exception e) {
                        throw new IllegalStateException(e);
                    }
                });
            }
            Path log = dir.resolve("clock.log");
            Process p = null;
            try {
                long warm = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                while (sent.get() < 1_000) {
                    assertThat(System.nanoTime()).as("the flood is running").isLessThan(warm);
                    Thread.sleep(20);
                }
                String java = org.ripv.it.TestJvms.java();
                p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), "-Dripv.host=flooded",
                        "org.ripv.examples.ClockService", "--server", "localhost:" + sys.server().registryPort(),
                        "--secret-file", sys.server().secretFile().toString())
                        .redirectErrorStream(true).redirectOutput(log.toFile()).start();
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                while (sys.server().serviceCount() == 0) {
                    assertThat(p.isAlive()).as("the service keeps running: " + Files.readString(log, StandardCharsets.UTF_8)).isTrue();
                    assertThat(System.nanoTime()).as("registered during the flood").isLessThan(end);
                    Thread.sleep(100);
                }
                long before = sent.get();
                Thread.sleep(3_000);
                assertThat(sent.get() - before).as("the flood went on").isGreaterThan(100);
                assertThat(p.isAlive()).as(Files.readString(log, StandardCharsets.UTF_8)).isTrue();
                assertThat(sys.server().serviceCount()).isEqualTo(1);
            } finally {
                flooding.set(false);
                flood.shutdown();
                assertThat(flood.awaitTermination(20, TimeUnit.SECONDS)).isTrue();
                if (p != null) {
                    p.destroy();
                    p.waitFor(20, TimeUnit.SECONDS);
                }
            }
        }
    }

    @Test
    void aServiceRetriesARefusalThatSaysToRegisterAgain() throws Exception {
        String secret = "0123456789abcdef".repeat(4);
        int port = FreePorts.one();
        Registry registry = LocateRegistry.createRegistry(port);
        Refusing server = new Refusing(secret);
        GenericRMIInterface stub = (GenericRMIInterface) UnicastRemoteObject.exportObject(server, 0);
        registry.rebind(GenericRMIInterface.BINDING, stub);
        ClockService clock = new ClockService("localhost");
        ServiceConnector c = ServiceConnector.connect(clock, new ServiceOptions("localhost", port, secret, 0, Duration.ofMillis(300)));
        try {
            assertThat(c.awaitRegistered(Duration.ofSeconds(20))).as("registered after being told to register again").isTrue();
            assertThat(server.tries.get()).isEqualTo(2);
        } finally {
            c.close();
            clock.stop();
            UnicastRemoteObject.unexportObject(server, true);
            UnicastRemoteObject.unexportObject(registry, true);
        }
    }

    /** A server that holds the secret and, the first time, refuses as a flooded server did. */
    static final class Refusing extends RegistryTakeoverAttackTest.Impostor {
        final String secret;
        final AtomicInteger tries = new AtomicInteger();

        Refusing(String secret) {
            this.secret = secret;
        }

        @Override
        public String challenge(String ns) {
            String mine = ServiceProof.nonce();
            return mine + " " + ServiceProof.serverProof(secret, ns, mine);
        }

        @Override
        public String register(ServiceDescriptor d, GenericRMIInterface s, String proof) {
            if (tries.incrementAndGet() == 1) {
                throw new SecurityException("the registration's challenge is unknown, used or expired; register again");
            }
            String[] w = proof.split(" ");
            return ServiceProof.serverProof(secret, w[0], w[1]);
        }
    }
}
