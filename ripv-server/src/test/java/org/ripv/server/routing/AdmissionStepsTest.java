package org.ripv.server.routing;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.reflect.Proxy;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.naming.MailboxAddress;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.server.dataloop.DataLoop;
import org.ripv.server.dataloop.ServiceCalls;
import org.ripv.server.files.FileStore;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.requests.PendingRequests;
import org.ripv.server.requests.RequestForwarder;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceRegistry;

/** Each admission step alone, then the chain: what it passes, what it refuses and with which code. */
class AdmissionStepsTest {
    static final String SERIAL = "<SerialPortServer>::<host>";
    static final String BOX = SERIAL + "ru29";

    PermitFile permit;
    final Supplier<PermitFile> permits = () -> permit;
    final List<ServiceReference> opened = new ArrayList<>();

    @TempDir
    Path dir;

    @BeforeEach
    void permitFile() throws Exception {
        permit = PermitFile.load(Files.write(dir.resolve("permit.txt"), List.of(
                "user alice pbkdf2-sha256$1000$AAAA$AAAA pilots",
                "user bob pbkdf2-sha256$1000$AAAA$AAAA",
                "allow @pilots * * *",
                "allow bob SerialPortServer * dir*")));
    }

    @AfterEach
    void closeReferences() {
        opened.forEach(ServiceReference::close);
    }

    static IncomingServerMessage request(String user, String mailbox, String body) {
        return new IncomingServerMessage(Header.request(7, mailbox, body, Priority.NORMAL)
                .withOrigin(new IdBadge("123456", user), List.of()));
    }

    /** A request that has passed the first steps: its address parsed, its service found. */
    Admitting admitted(String user, String body, ServiceReference ref) {
        Admitting a = new Admitting(request(user, ref == null ? BOX : ref.descriptor().name() + "ru29", body));
        a.address(MailboxAddress.parse(a.request().header().mailboxAddress()));
        if (ref != null) {
            a.service(ref);
        }
        a.user(permit.user(user).orElse(null));
        return a;
    }

    ServiceReference service(String name, String sid, List<String> attach, List<String> download) {
        GenericRMIInterface stub = (GenericRMIInterface) Proxy.newProxyInstance(getClass().getClassLoader(),
                new Class<?>[] {GenericRMIInterface.class}, (p, m, args) -> m.getName().equals("toString") ? "stub" : null);
        ServiceReference ref = new ServiceReference(new ServiceDescriptor(name, sid, "", "", attach, download, 0), stub, "t",
                (r, q, e) -> { }, 0);
        opened.add(ref);
        return ref;
    }

    ServiceReference serial() {
        return service(SERIAL, Ids.SID_SERIAL, List.of("put "), List.of());
    }

    static void refused(AdmissionStep.Verdict v, ErrorCode code, String text) {
        assertThat(v.passed()).isFalse();
        assertThat(v.refusal().footer().errorCode()).isEqualTo(code);
        assertThat(v.refusal().footer().replyText()).contains(text);
    }

    @Test
    void mailboxChosenParsesTheAddressOrRefuses() {
        MailboxChosen step = new MailboxChosen();
        refused(step.check(new Admitting(request("alice", "", "dir"))), ErrorCode.BAD_REQUEST, "no mailbox chosen for 'dir'");
        refused(step.check(new Admitting(request("alice", "not an address", "dir"))), ErrorCode.UNKNOWN_MAILBOX, "");
        Admitting a = new Admitting(request("alice", BOX, "dir"));
        assertThat(step.check(a).passed()).isTrue();
        assertThat(a.address().handle()).isEqualTo("ru29");
    }

    @Test
    void serviceRegisteredFindsTheServiceOrRefuses() {
        ServiceRegistry registry = new ServiceRegistry();
        Admitting a = new Admitting(request("alice", BOX, "dir"));
        new MailboxChosen().check(a);
        refused(new ServiceRegistered(registry).check(a), ErrorCode.UNKNOWN_SERVICE, "no service " + SERIAL + " is registered");
        assertThat(a.refuse(ErrorCode.NONE, "").footer().serviceId()).isEqualTo(Ids.FID_NONE);
    }

    @Test
    void oneLineRefusesEmptyAndMultiLineCommands() {
        ServiceReference ref = serial();
        OneLine step = new OneLine();
        refused(step.check(admitted("alice", "  ", ref)), ErrorCode.BAD_REQUEST, "an empty command");
        AdmissionStep.Verdict two = step.check(admitted("alice", "dir\rdel GLIDER.CFG", ref));
        refused(two, ErrorCode.BAD_REQUEST, "");
        assertThat(two.refusal().footer().serviceId()).isEqualTo(Ids.SID_SERIAL);
        assertThat(step.check(admitted("alice", "dir /w", ref)).passed()).isTrue();
    }

    @Test
    void userKnownRefusesSomeoneNoLongerInThePermitFile() {
        Admitting gone = admitted("carol", "dir", serial());
        refused(new UserKnown(permits).check(gone), ErrorCode.FORBIDDEN, "user 'carol' is no longer in the permit file");
        Admitting bob = new Admitting(request("bob", BOX, "dir"));
        assertThat(new UserKnown(permits).check(bob).passed()).isTrue();
        assertThat(bob.user().name()).isEqualTo("bob");
    }

    @Test
    void permitAllowsFollowsTheRules() {
        ServiceReference ref = serial();
        PermitAllows step = new PermitAllows(permits);
        assertThat(step.check(admitted("bob", "dir", ref)).passed()).isTrue();
        refused(step.check(admitted("bob", "del GLIDER.CFG", ref)), ErrorCode.FORBIDDEN, "user 'bob' may not send 'del GLIDER.CFG' to " + BOX);
        assertThat(step.check(admitted("alice", "del GLIDER.CFG", ref)).passed()).isTrue();
    }

    @Test
    void lockFreeRefusesOthersWhileTheLockHolds() {
        Map<String, OperatorLock> locks = new ConcurrentHashMap<>();
        LockFree step = new LockFree(locks);
        ServiceReference ref = serial();
        assertThat(step.check(admitted("bob", "dir", ref)).passed()).isTrue();
        locks.put(BOX, new OperatorLock("alice", "111111", System.currentTimeMillis() + 60_000));
        refused(step.check(admitted("bob", "dir", ref)), ErrorCode.MAILBOX_LOCKED, BOX + " is locked by alice until");
        assertThat(step.check(admitted("alice", "dir", ref)).passed()).as("the holder").isTrue();
        locks.put(BOX, new OperatorLock("alice", "111111", System.currentTimeMillis() - 1));
        assertThat(step.check(admitted("bob", "dir", ref)).passed()).as("an expired lock").isTrue();
    }

    @Test
    void plotTakeoverAnswersAPlotFromDataItself() {
        List<OutgoingServerMessage> out = new ArrayList<>();
        ServiceCalls none = new ServiceCalls() {
            @Override
            public List<String> services(String sid) {
                return List.of();
            }

            @Override
            public boolean permitted(String user, String mailbox, String body) {
                return true;
            }

            @Override
            public String whyNotDownload(String user, String downloadName) {
                return null;
            }

            @Override
            public java.util.concurrent.CompletableFuture<org.ripv.messages.Footer> call(String mailbox, String body, String user,
                    List<String> roles, org.ripv.messages.Attachment attachment,
                    java.util.function.Consumer<org.ripv.messages.Footer> progress) {
                throw new AssertionError("no call expected");
            }
        };
        PlotTakeover step = new PlotTakeover(new DataLoop(none, dir.resolve("ingest.properties")), out::add);
        ServiceReference vis = service("<DataVisServer>::<host>", Ids.SID_DATAVIS, List.of(), List.of("vis:file"));
        assertThat(step.check(admitted("alice", "vis:file a.dba", vis)).passed()).isTrue();
        assertThat(step.check(admitted("alice", "vis:sql SELECT 1", serial())).passed()).as("not a DataVisServer").isTrue();
        AdmissionStep.Verdict v = step.check(admitted("alice", "vis:sql SELECT 1", vis));
        assertThat(v.taken()).isTrue();
        assertThat(out).hasSize(1); // no DatabaseServer to ask: answered at once
        assertThat(out.get(0).footer().errorCode()).isNotEqualTo(ErrorCode.NONE);
    }

    @Test
    void toVehicleFolderRuleKeepsAVehicleToItsOwnFolder() {
        ToVehicleFolderRule step = new ToVehicleFolderRule();
        ServiceReference ref = serial();
        String own = "to-vehicle/" + FileStore.folderFor(BOX) + "/";
        assertThat(step.check(admitted("alice", "tovehicle:put " + own + "goto_l10.ma", ref)).passed()).isTrue();
        refused(step.check(admitted("alice", "tovehicle:put to-vehicle/other/goto_l10.ma", ref)), ErrorCode.BAD_FILE_NAME,
                "tovehicle:put sends a file of " + BOX + "'s own folder");
        refused(step.check(admitted("alice", "tovehicle:put " + own + "a b", ref)), ErrorCode.BAD_FILE_NAME, "");
        assertThat(step.check(admitted("alice", "dir", ref)).passed()).isTrue();
    }

    @Test
    void attachmentRuleAttachesTheNamedUploadOrRefuses() throws Exception {
        FileStore files = new FileStore(dir.resolve("upload"), dir.resolve("download"), 1 << 20);
        Files.writeString(files.uploadDir().resolve("goto_l10.ma"), "behavior_name=goto_list");
        AttachmentRule step = new AttachmentRule(files, permits);
        ServiceReference ref = serial();
        Admitting put = admitted("alice", "put goto_l10.ma", ref);
        assertThat(step.check(put).passed()).isTrue();
        assertThat(put.attachment().name()).isEqualTo("goto_l10.ma");
        assertThat(new String(put.attachment().data())).isEqualTo("behavior_name=goto_list");
        ServiceReference send = service("<SendServer>::<host>", "123123", List.of("send"), List.of());
        refused(step.check(admitted("alice", "send", send)), ErrorCode.BAD_FILE_NAME,
                "'send' needs the name of a file in the upload directory");
        refused(step.check(admitted("alice", "put missing.ma", ref)), ErrorCode.BAD_FILE_NAME, "missing.ma");
        Admitting dir = admitted("alice", "dir", ref);
        assertThat(step.check(dir).passed()).isTrue();
        assertThat(dir.attachment()).isNull();
    }

    @Test
    void theChainForwardsWhatEveryStepPassesAndStopsAtTheFirstRefusal() throws Exception {
        ServiceRegistry registry = new ServiceRegistry();
        java.util.concurrent.BlockingQueue<IncomingServiceMessage> sent = new java.util.concurrent.LinkedBlockingQueue<>();
        GenericRMIInterface stub = (GenericRMIInterface) Proxy.newProxyInstance(getClass().getClassLoader(),
                new Class<?>[] {GenericRMIInterface.class}, (p, m, args) -> {
                    if (m.getName().equals("serviceRequest")) {
                        sent.add((IncomingServiceMessage) args[1]);
                    } else if (m.getName().equals("serviceRequests")) {
                        @SuppressWarnings("unchecked")
                        List<IncomingServiceMessage> l = (List<IncomingServiceMessage>) args[1];
                        sent.addAll(l);
                    }
                    return m.getName().equals("toString") ? "stub" : null;
                });
        ServiceReference ref = new ServiceReference(new ServiceDescriptor(SERIAL, Ids.SID_SERIAL, "", "", List.of(), List.of(), 0),
                stub, "t", (r, q, e) -> { }, 0);
        opened.add(ref);
        List<OutgoingServerMessage> out = new ArrayList<>();
        java.util.concurrent.ScheduledExecutorService timers = java.util.concurrent.Executors.newSingleThreadScheduledExecutor();
        try {
            PendingRequests pending = new PendingRequests(timers, java.time.Duration.ofMinutes(1), p -> { });
            Admission chain = new Admission(List.of(new MailboxChosen(), new ServiceRegistered(registry), new OneLine(),
                    new UserKnown(permits), new PermitAllows(permits)), new RequestForwarder(pending, out::add));
            OutgoingServerMessage refusal = chain.route(request("bob", BOX, "dir"));
            assertThat(refusal.footer().errorCode()).isEqualTo(ErrorCode.UNKNOWN_SERVICE); // not registered yet
            registry.put(ref, (old, young) -> young);
            assertThat(chain.route(request("bob", BOX, "del x")).footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(chain.route(request("bob", BOX, "dir"))).isNull();
            IncomingServiceMessage forwarded = sent.poll(5, java.util.concurrent.TimeUnit.SECONDS);
            assertThat(forwarded).isNotNull();
            assertThat(forwarded.header().serviceDestination()).isEqualTo(SERIAL);
            assertThat(pending.get("123456", 7)).isNotNull();
            assertThat(out).isEmpty();
        } finally {
            timers.shutdownNow();
        }
    }
}
