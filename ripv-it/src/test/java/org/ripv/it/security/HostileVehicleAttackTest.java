package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.naming.Handles;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 10, attack 6: asked for {@code OVER}, a hostile vehicle sends block 0 named
 * {@code MISSION1.LOG}. It must not replace the honest glider's MISSION1.LOG, nor store anything
 * under a name the operator did not ask for; each vehicle's downloads live in a folder of their own.
 */
class HostileVehicleAttackTest {
    static final Duration T = Duration.ofSeconds(60);
    static final YmodemConfig YMODEM = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10),
            Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(1));

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator honest;
    HostileVehicle hostile;
    String honestBox;
    String hostileBox;
    String honestHandle;
    String hostileHandle;
    String honestFolder;
    String hostileFolder;

    @BeforeEach
    void start() throws Exception {
        honest = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(30), YMODEM);
        String honestDevice = "tcp://127.0.0.1:" + honest.listen(0);
        hostile = new HostileVehicle(YMODEM);
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("otto", "operators");
        SerialPortServer serial = new SerialPortServer("localhost", List.of(link(honestDevice), link(hostile.device())),
                null, false, dir.resolve("work"));
        sys.register(serial);
        honestHandle = Handles.forLink(honestDevice);
        hostileHandle = Handles.forLink(hostile.device());
        honestBox = "<SerialPortServer>::<localhost>" + honestHandle;
        hostileBox = "<SerialPortServer>::<localhost>" + hostileHandle;
        honestFolder = org.ripv.server.files.FileStore.folderFor(honestBox);
        hostileFolder = org.ripv.server.files.FileStore.folderFor(hostileBox);
    }

    private static LinkSettings link(String device) {
        return LinkSettings.defaults(device).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(YMODEM);
    }

    @AfterEach
    void stop() throws Exception {
        if (sys != null) {
            sys.close();
        }
        honest.close();
        hostile.close();
    }

    @Test
    void aBlockZeroNameThatWasNotAskedForIsRefusedAndReplacesNothing() throws Exception {
        ClientSocketHandler otto = sys.login("otto");
        byte[] real = Files.readAllBytes(honest.directory().resolve("MISSION1.LOG"));
        OutgoingServerMessage got = otto.call(honestBox, "ymodem:get MISSION1.LOG", Priority.NORMAL, T, null);
        assertThat(got.status()).as(got.footer().replyText()).isEqualTo(Status.OK);
        assertThat(got.footer().replyText()).contains("stored in the download directory as " + honestFolder + "/MISSION1.LOG");
        Path stored = sys.downloadDir().resolve(honestFolder).resolve("MISSION1.LOG");
        assertThat(Files.readAllBytes(stored)).isEqualTo(real);

        // asked for OVER, the hostile vehicle sends MISSION1.LOG (and a traversal attempt)
        byte[] evil = "evil mission".getBytes(StandardCharsets.US_ASCII);
        hostile.batch = () -> List.of(SendFile.of("MISSION1.LOG", evil));
        OutgoingServerMessage r = otto.call(hostileBox, "ymodem:get OVER", Priority.NORMAL, T, null);
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.TRANSFER_FAILED);
        assertThat(r.footer().replyText()).contains("'MISSION1.LOG', which was not asked for; refused");
        assertThat(Files.readAllBytes(stored)).as("the honest glider's file is untouched").isEqualTo(real);
        assertThat(Files.exists(sys.downloadDir().resolve("MISSION1.LOG"))).isFalse();
        assertThat(Files.exists(sys.downloadDir().resolve(hostileFolder).resolve("MISSION1.LOG"))).isFalse();

        // a batch with the asked file and an extra: the asked one is stored in the vehicle's own folder, with a warning
        hostile.batch = () -> List.of(SendFile.of("over", "over".getBytes()), SendFile.of("MISSION1.LOG", evil));
        r = otto.call(hostileBox, "ymodem:get OVER", Priority.NORMAL, T, null);
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(r.footer().replyText()).contains("warning: the vehicle sent 'MISSION1.LOG'")
                .contains(hostileFolder + "/OVER");
        assertThat(Files.readString(sys.downloadDir().resolve(hostileFolder).resolve("OVER"))).isEqualTo("over");
        assertThat(Files.readAllBytes(stored)).isEqualTo(real);

        // the same name from two vehicles: both kept apart; ?dlfiles lists FOLDER/NAME, and get fetches each
        hostile.batch = () -> List.of(SendFile.of("MISSION1.LOG", evil));
        r = otto.call(hostileBox, "ymodem:get MISSION1.LOG", Priority.NORMAL, T, null);
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(Files.readAllBytes(stored)).isEqualTo(real);
        FileListing dl = (FileListing) otto.call("", "?dlfiles", Priority.NORMAL, T, null).footer().result();
        assertThat(dl.files()).extracting(FileListing.Entry::name)
                .contains(honestFolder + "/MISSION1.LOG", hostileFolder + "/MISSION1.LOG", hostileFolder + "/OVER");
        Path mine = otto.download(honestFolder + "/MISSION1.LOG", dir.resolve("here"), null);
        assertThat(mine.getFileName().toString()).isEqualTo("MISSION1.LOG");
        assertThat(Files.readAllBytes(mine)).isEqualTo(real);
        OutgoingServerMessage ambiguous = otto.call("", "?download MISSION1.LOG 0 100", Priority.NORMAL, T, null);
        assertThat(ambiguous.footer().replyText()).contains("several MailBoxes");
        for (String traversal : List.of("../permit.txt", honestFolder + "/../../permit.txt", "../../etc/passwd")) {
            OutgoingServerMessage t = otto.call("", "?download " + traversal + " 0 100", Priority.NORMAL, T, null);
            assertThat(t.status()).as(traversal).isEqualTo(Status.ERROR);
        }
    }
}
