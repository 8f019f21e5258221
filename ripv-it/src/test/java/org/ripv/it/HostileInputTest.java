package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.rmi.registry.LocateRegistry;
import java.time.Duration;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.examples.ClockService;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.Status;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.server.ServerConfig;
import org.ripv.wire.FrameCodec;

/** Bad input of every kind gets a clear error, writes nothing, and the server serves the next client. */
class HostileInputTest {
    static final Duration T = Duration.ofSeconds(20);
    static final String CLOCK = "<ClockService>::<localhost>TTY1";

    @TempDir
    Path dir;
    TestSystem sys;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(ServerConfig.forTests(dir.resolve("server")).withMaxUpload(64 * 1024)
                .withRequestTimeout(Duration.ofSeconds(3)));
        sys.user("alice", "operators");
        sys.register(new ClockService("localhost"));
    }

    @AfterEach
    void stop() {
        sys.close();
    }

    private void assertNothingWritten() throws IOException {
        try (Stream<Path> files = Files.walk(sys.dataDir())) {
            // audit/ is the audit trail (the log-in, the registration), and download/*/.mailbox the
            // marker of a registered MailBox's own folder: neither is the hostile input's doing
            assertThat(files.filter(Files::isRegularFile).map(p -> sys.dataDir().relativize(p).toString())
                    .filter(name -> !name.startsWith("audit/"))
                    .filter(name -> !(name.startsWith("download/") && name.endsWith("/.mailbox"))))
                    .containsExactlyInAnyOrder("permit.txt", "service.secret", "tls/server.p12", "tls/server.pass");
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"../x", "..\\x", "/etc/passwd", ".hidden", "nul\0byte", "sub/dir.txt"})
    void uploadsWithBadNamesAreRefusedAndWriteNothing(String name) throws Exception {
        ClientSocketHandler c = sys.login("alice");
        Header h = new Header(c.nextId(), new IdBadge("000000", ""), List.of(), "", "", "?upload " + name + " 0 5",
                Priority.NORMAL, new Attachment(name, "hello".getBytes()));
        OutgoingServerMessage r = c.send(h, null).get(20, TimeUnit.SECONDS);
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().errorCode()).isIn(ErrorCode.BAD_REQUEST, ErrorCode.BAD_FILE_NAME);
        assertThat(r.footer().replyText()).isNotBlank();
        assertNothingWritten();
    }

    @Test
    void aNameOf300CharactersIsRefused() throws Exception {
        Path local = dir.resolve("local.bin");
        Files.write(local, new byte[10]);
        ClientSocketHandler c = sys.login("alice");
        assertThatThrownBy(() -> c.upload(local, "a".repeat(300), null)).isInstanceOf(RipvErrorException.class)
                .hasMessageContaining("300 characters");
        assertNothingWritten();
    }

    @Test
    void anUploadOverTheLimitIsRefusedAndLeavesNoFile() throws Exception {
        Path local = dir.resolve("big.bin");
        Files.write(local, new byte[64 * 1024 + 1]);
        ClientSocketHandler c = sys.login("alice");
        assertThatThrownBy(() -> c.upload(local, "big.bin", null)).isInstanceOf(RipvErrorException.class)
                .hasMessageContaining("limit");
        assertNothingWritten();
    }

    @Test
    void aGoodUploadArrivesWholeAndDownloadsBack() throws Exception {
        Path local = dir.resolve("ok.bin");
        byte[] data = new byte[60_000];
        new java.util.Random(7).nextBytes(data);
        Files.write(local, data);
        ClientSocketHandler c = sys.login("alice");
        OutgoingServerMessage r = c.upload(local, "ok.bin", null);
        assertThat(r.footer().replyText()).contains("stored ok.bin");
        assertThat(Files.readAllBytes(sys.uploadDir().resolve("ok.bin"))).isEqualTo(data);
        Files.write(sys.downloadDir().resolve("log.dat"), data);
        Path got = c.download("log.dat", dir.resolve("back"), null);
        assertThat(Files.readAllBytes(got)).isEqualTo(data);
        assertThatThrownBy(() -> c.download("../permit.txt", dir.resolve("back"), null)).isInstanceOf(IOException.class)
                .hasMessageContaining("outside");
        OutgoingServerMessage escape = c.call("", "?download ../permit.txt 0 100", Priority.NORMAL, T, null);
        assertThat(escape.footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
        assertThat(escape.footer().replyText()).contains("slash");
    }

    /** Would set the flag if the server ever deserialized it. */
    static final class Evil implements Serializable {
        static volatile boolean ran;
        private static final long serialVersionUID = 1L;

        private void readObject(java.io.ObjectInputStream in) {
            ran = true;
        }
    }

    static byte[] serialize(Object o) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(b)) {
            out.writeObject(o);
        }
        return b.toByteArray();
    }

    static byte[] hashSetBomb(int depth) throws IOException {
        Set<Object> root = new HashSet<>();
        Set<Object> s1 = root;
        Set<Object> s2 = new HashSet<>();
        for (int i = 0; i < depth; i++) {
            Set<Object> t1 = new HashSet<>();
            Set<Object> t2 = new HashSet<>();
            t1.add("x");
            s1.add(t1);
            s1.add(t2);
            s2.add(t1);
            s2.add(t2);
            s1 = t1;
            s2 = t2;
        }
        return serialize(root);
    }

    /** Opens a raw connection, greets, sends the body as one frame, and expects to be dropped. */
    private void assertDropped(byte[] frameBody, boolean greet) throws Exception {
        try (Socket s = sys.rawSocket()) {
            s.setSoTimeout(10_000);
            DataOutputStream out = new DataOutputStream(s.getOutputStream());
            InputStream in = s.getInputStream();
            if (greet) {
                FrameCodec.writeGreeting(out);
                FrameCodec.readGreeting(new DataInputStream(in));
                FrameCodec.writeRawFrame(out, frameBody);
            } else {
                out.write(frameBody);
                out.flush();
            }
            assertThat(readEnd(in)).as("the server closes a connection that breaks the protocol").isEqualTo(-1);
        }
        ClientSocketHandler next = sys.login("alice");
        assertThat(next.call(CLOCK, "echo still here", Priority.NORMAL, T, null).footer().replyText()).isEqualTo("still here");
    }

    /** -1 when the server closed the connection (over TLS an abrupt close may show as a reset). */
    private static int readEnd(InputStream in) throws IOException {
        try {
            return in.read();
        } catch (java.net.SocketException | javax.net.ssl.SSLException e) {
            return -1;
        }
    }

    @Test
    void garbageBytesCloseTheConnectionAndTheNextClientIsServed() throws Exception {
        byte[] garbage = new byte[4096];
        new java.util.Random(1).nextBytes(garbage);
        assertDropped(garbage, false);
        assertDropped(garbage, true);
    }

    @Test
    void theSixByteNullPointerStreamIsRejected() throws Exception {
        assertDropped(new byte[] {(byte) 0xAC, (byte) 0xED, 0x00, 0x05, 0x7E, 0x70}, true);
    }

    @Test
    void aHashSetDepthBombIsRejected() throws Exception {
        assertDropped(hashSetBomb(60), true);
    }

    @Test
    void aClassOutsideTheAllowlistIsNeverInstantiated() throws Exception {
        Evil.ran = false;
        assertDropped(serialize(new Evil()), true);
        assertThat(Evil.ran).isFalse();
    }

    @Test
    void aHugeFrameLengthIsRejectedWithoutAllocating() throws Exception {
        try (Socket s = sys.rawSocket()) {
            DataOutputStream out = new DataOutputStream(s.getOutputStream());
            FrameCodec.writeGreeting(out);
            FrameCodec.readGreeting(new DataInputStream(s.getInputStream()));
            out.writeInt(Integer.MAX_VALUE);
            out.flush();
            s.setSoTimeout(10_000);
            assertThat(readEnd(s.getInputStream())).isEqualTo(-1);
        }
    }

    @Test
    void aRegistrationWithoutTheSecretIsRefused() throws Exception {
        GenericRMIInterface server = (GenericRMIInterface) LocateRegistry.getRegistry("localhost", sys.server().registryPort())
                .lookup(GenericRMIInterface.BINDING);
        ServiceDescriptor d = new ServiceDescriptor("<Fake>::<localhost>", "123123", "", "", List.of());
        assertThatThrownBy(() -> server.register(d, null, "guess")).isInstanceOf(SecurityException.class)
                .hasMessageContaining("secret");
        assertThatThrownBy(() -> server.register(d, null, null)).isInstanceOf(SecurityException.class);
        assertThatThrownBy(() -> server.serviceReply("forged", null)).isInstanceOf(SecurityException.class);
        assertThat(server.heartbeat("forged")).isFalse();
    }

    @Test
    void aServiceThatNeverAnswersGivesATimeoutErrorAndTheLateReplyIsDropped() throws Exception {
        ClientSocketHandler c = sys.login("alice");
        java.util.List<OutgoingServerMessage> finals = new java.util.concurrent.CopyOnWriteArrayList<>();
        c.addListener(r -> {
            if (r.status().isFinal() && !r.header().body().startsWith("?")) {
                finals.add(r);
            }
        });
        CompletableFuture<OutgoingServerMessage> running = c.send(CLOCK, "sleep 5000", Priority.NORMAL, null);
        CompletableFuture<OutgoingServerMessage> queued = c.send(CLOCK, "echo queued behind", Priority.NORMAL, null);
        OutgoingServerMessage r = running.get(20, TimeUnit.SECONDS);
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.TIMEOUT);
        assertThat(r.footer().replyText()).contains("did not answer").contains("sleep 5000").contains("may still complete");
        OutgoingServerMessage q = queued.get(20, TimeUnit.SECONDS);
        assertThat(q.footer().errorCode()).isEqualTo(ErrorCode.TIMEOUT);
        assertThat(q.footer().replyText()).contains("withdrawn and will not run");
        // Once the sleep has ended the MailBox serves again, and the withdrawn echo never ran.
        awaitIdle(c);
        assertThat(c.call(CLOCK, "echo after", Priority.NORMAL, T, null).footer().replyText()).isEqualTo("after");
        assertThat(finals).extracting(m -> m.header().body())
                .containsExactlyInAnyOrder("sleep 5000", "echo queued behind", "echo after");
        assertThat(finals.get(2).header().body()).isEqualTo("echo after");
    }

    private static void awaitIdle(ClientSocketHandler c) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (((org.ripv.messages.MailboxStatus) c.call("", "?status " + CLOCK, Priority.NORMAL, T, null).footer().result()).busy()) {
            assertThat(System.nanoTime()).as("the MailBox becomes idle").isLessThan(end);
            Thread.sleep(50);
        }
    }

    @Test
    void aClientThatVanishesCostsTheServerNothing() throws Exception {
        ClientSocketHandler gone = sys.login("alice");
        gone.send(CLOCK, "sleep 500", Priority.NORMAL, null);
        gone.close();
        ClientSocketHandler next = sys.login("alice");
        assertThat(next.call(CLOCK, "echo fine", Priority.NORMAL, T, null).footer().replyText()).isEqualTo("fine");
    }

    @Test
    void aServiceKilledMidRequestGivesTheClientAnError() throws Exception {
        String java = TestJvms.java();
        Process p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), "-Dripv.host=killme",
                "org.ripv.examples.ClockService", "--server", "localhost:" + sys.server().registryPort(),
                "--secret-file", sys.server().secretFile().toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("svc.log").toFile()).start();
        try {
            ClientSocketHandler c = sys.login("alice");
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (!c.call("", "?services", Priority.NORMAL, T, null).footer().replyText().contains("killme")) {
                assertThat(System.nanoTime()).as("the service process registers").isLessThan(end);
                Thread.sleep(100);
            }
            CompletableFuture<OutgoingServerMessage> f = c.send("<ClockService>::<killme>TTY1", "sleep 2500", Priority.NORMAL, null);
            Thread.sleep(300);
            p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            OutgoingServerMessage r = f.get(20, TimeUnit.SECONDS);
            assertThat(r.status()).isEqualTo(Status.ERROR);
            assertThat(r.footer().errorCode()).isIn(ErrorCode.SERVICE_GONE, ErrorCode.TIMEOUT);
            long gone = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            // Listed no more (a line "<ClockService>::<killme>  LOST at …" says why it went).
            while (c.call("", "?services", Priority.NORMAL, T, null).footer().replyText().contains("<killme>  SID")) {
                assertThat(System.nanoTime()).as("the dead service leaves the list").isLessThan(gone);
                Thread.sleep(100);
            }
        } finally {
            p.destroyForcibly();
        }
    }
}
