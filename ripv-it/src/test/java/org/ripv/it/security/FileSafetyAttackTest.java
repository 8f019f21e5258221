package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 10, attacks 2 and 7 (server side): an upload never silently replaces an operator's file,
 * replacing needs a right, keep picks a new name, deleting needs a right, a user's uploads are
 * bounded by a quota; the data directory, the stores and the serial work files are owner-only,
 * and partial files of a killed run are cleaned at start.
 */
class FileSafetyAttackTest {
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    Path dir;
    TestSystem sys;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("otto", "operators").user("olga", "observers").user("mallory", "observers");
        sys.rules("quota mallory 100K",
                "allow @operators * * *",
                "allow @observers RIPVServer * ?upload*",
                "allow @observers RIPVServer * ?download *");
    }

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    private static OutgoingServerMessage upload(ClientSocketHandler c, String name, byte[] data, String mode) throws Exception {
        Header h = new Header(c.nextId(), new IdBadge("000000", ""), List.of(), "", "",
                "?upload " + name + " 0 " + data.length + (mode == null ? "" : " " + mode), Priority.NORMAL,
                new Attachment(name, data));
        return c.send(h, null).get(T.toSeconds(), TimeUnit.SECONDS);
    }

    private String stored(String name) throws Exception {
        return Files.readString(sys.uploadDir().resolve(name), StandardCharsets.UTF_8);
    }

    @Test
    void anUploadNeverReplacesAnotherUsersFileSilently() throws Exception {
        ClientSocketHandler otto = sys.login("otto");
        ClientSocketHandler mallory = sys.login("mallory");
        assertThat(upload(otto, "mission.bin", "the real mission".getBytes(), null).status()).isEqualTo(Status.OK);

        OutgoingServerMessage plain = upload(mallory, "mission.bin", "evil".getBytes(), null);
        assertThat(plain.footer().errorCode()).isEqualTo(ErrorCode.FILE_EXISTS);
        assertThat(plain.footer().serviceId()).isEqualTo(Ids.FID_UPLOAD);
        assertThat(plain.footer().replyText()).contains("replace").contains("keep");

        OutgoingServerMessage replace = upload(mallory, "mission.bin", "evil".getBytes(), "replace");
        assertThat(replace.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(stored("mission.bin")).isEqualTo("the real mission");

        OutgoingServerMessage keep = upload(mallory, "mission.bin", "evil".getBytes(), "keep");
        assertThat(keep.status()).as(keep.footer().replyText()).isEqualTo(Status.OK);
        assertThat(keep.footer().replyText()).contains("stored as mission(1).bin");
        assertThat(stored("mission.bin")).isEqualTo("the real mission");
        assertThat(stored("mission(1).bin")).isEqualTo("evil");

        // the client's put (no mode) gets the same refusal
        Path local = dir.resolve("mission.bin");
        Files.writeString(local, "again");
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> mallory.upload(local, "mission.bin", null))
                .hasMessageContaining("already");

        // an operator holds the right to replace, and to delete; an observer holds neither
        assertThat(upload(otto, "mission.bin", "mission v2".getBytes(), "replace").status()).isEqualTo(Status.OK);
        assertThat(stored("mission.bin")).isEqualTo("mission v2");
        OutgoingServerMessage del = mallory.call("", "?delete mission.bin", Priority.NORMAL, T, null);
        assertThat(del.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        del = otto.call("", "?delete mission(1).bin", Priority.NORMAL, T, null);
        assertThat(del.status()).as(del.footer().replyText()).isEqualTo(Status.OK);
        assertThat(del.footer().serviceId()).isEqualTo(Ids.FID_DELETE);
        assertThat(Files.exists(sys.uploadDir().resolve("mission(1).bin"))).isFalse();
        assertThat(otto.call("", "?delete ../permit.txt", Priority.NORMAL, T, null).status()).isEqualTo(Status.ERROR);
        assertThat(Files.exists(sys.dataDir().resolve("permit.txt"))).isTrue();
    }

    @Test
    void aUsersUploadsAreBoundedByTheirQuota() throws Exception {
        ClientSocketHandler mallory = sys.login("mallory");
        assertThat(upload(mallory, "a.bin", new byte[60 * 1024], null).status()).isEqualTo(Status.OK);
        OutgoingServerMessage over = upload(mallory, "b.bin", new byte[60 * 1024], null);
        assertThat(over.footer().errorCode()).isEqualTo(ErrorCode.TOO_LARGE);
        assertThat(over.footer().replyText()).contains("quota");
        assertThat(Files.exists(sys.uploadDir().resolve("b.bin"))).isFalse();
        // others have the default quota
        assertThat(upload(sys.login("olga"), "b.bin", new byte[60 * 1024], null).status()).isEqualTo(Status.OK);
    }

    @Test
    void ordinaryUsersSeeNoServerPaths() throws Exception {
        ClientSocketHandler mallory = sys.login("mallory");
        String root = sys.dataDir().toAbsolutePath().toString();
        for (String command : List.of("?dldir", "?uldir", "?dlfiles", "?ulfiles")) {
            OutgoingServerMessage r = mallory.call("", command, Priority.NORMAL, T, null);
            assertThat(r.footer().replyText()).as(command).doesNotContain(root).doesNotContain(sys.downloadDir().toString());
            assertThat(String.valueOf(r.footer().result())).as(command).doesNotContain(sys.downloadDir().toString())
                    .doesNotContain(sys.uploadDir().toString());
        }
        assertThat(sys.login("otto").call("", "?dldir", Priority.NORMAL, T, null).footer().replyText())
                .isEqualTo(sys.downloadDir().toString());
    }

    @Test
    void serverAndSerialFilesAreOwnerOnlyAndStalePartialFilesGo() throws Exception {
        YmodemConfig ymodem = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10), Duration.ofSeconds(1),
                Duration.ofSeconds(2), Duration.ofSeconds(1));
        try (GliderSimulator glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(30), ymodem)) {
            String device = "tcp://127.0.0.1:" + glider.listen(0);
            String handle = org.ripv.naming.Handles.forLink(device);
            Path work = dir.resolve("work");
            // what a killed run left behind
            Files.createDirectories(work.resolve(handle).resolve("get-3"));
            Files.writeString(work.resolve(handle).resolve("get-3").resolve(".MISSION1.LOG.part"), "half");
            Files.writeString(work.resolve(handle).resolve(".OLD.part"), "half");
            SerialPortServer serial = new SerialPortServer("localhost", List.of(LinkSettings.defaults(device)
                    .withIdleTimeout(Duration.ofSeconds(1)).withReconnectEvery(Duration.ofMillis(300)).withYmodem(ymodem)),
                    null, false, work);
            sys.register(serial);
            try (Stream<Path> left = Files.walk(work)) {
                assertThat(left.filter(Files::isRegularFile)).as("stale partial files removed at start").isEmpty();
            }
            ClientSocketHandler otto = sys.login("otto");
            upload(otto, "up.bin", "x".getBytes(), null);
            OutgoingServerMessage got = otto.call("<SerialPortServer>::<localhost>" + handle, "ymodem:get MISSION1.LOG",
                    Priority.NORMAL, T, null);
            assertThat(got.status()).as(got.footer().replyText()).isEqualTo(Status.OK);
            String folder = org.ripv.server.files.FileStore.folderFor("<SerialPortServer>::<localhost>" + handle);
            for (Path p : List.of(sys.dataDir(), sys.uploadDir(), sys.downloadDir(), sys.downloadDir().resolve(folder),
                    work.resolve(handle))) {
                assertThat(mode(p)).as(p.toString()).isEqualTo("rwx------");
            }
            for (Path p : List.of(sys.uploadDir().resolve("up.bin"), sys.downloadDir().resolve(folder).resolve("MISSION1.LOG"),
                    sys.dataDir().resolve("permit.txt"), sys.dataDir().resolve("service.secret"))) {
                assertThat(mode(p)).as(p.toString()).isEqualTo("rw-------");
            }
        }
    }

    private static String mode(Path p) throws Exception {
        return PosixFilePermissions.toString(Files.getPosixFilePermissions(p));
    }
}
