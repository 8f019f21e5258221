package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.files.FileStore;
import org.ripv.services.datavis.DataVisServer;
import org.ripv.services.serial.CallSettings;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.VehicleLink;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 23, items 4 and 5: two services whose MailBoxes share a handle ({@code name=veh1} on two
 * glider PCs) wrote into the same {@code download/veh1/} folder and overwrote each other's files;
 * and a user with rights on the DataVisServer only attached another vehicle's download with
 * {@code vis:file}, with no read check.
 */
class DownloadCollisionAttackTest {
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path dir;

    @Test
    void twoVehiclesWithOneHandleKeepTheirOwnFilesAndOnlyTheirReadersFetchThem() throws Exception {
        try (GliderSimulator one = new GliderSimulator(dir.resolve("g1"), Duration.ofSeconds(30), YmodemConfig.lrzsz());
             GliderSimulator two = new GliderSimulator(dir.resolve("g2"), Duration.ofSeconds(30), YmodemConfig.lrzsz());
             TestSystem sys = TestSystem.start(dir.resolve("sys"))) {
            Files.writeString(one.directory().resolve("MISSION1.LOG"), "the first glider's log\n", StandardCharsets.US_ASCII);
            Files.writeString(two.directory().resolve("MISSION1.LOG"), "the second glider's log, longer\n", StandardCharsets.US_ASCII);
            sys.user("otto", "operators").user("uri").user("ann").user("dora");
            sys.rules("allow @operators * * *",
                    "allow uri SerialPortServer veh1 ?read",
                    "deny  uri SerialPortServer * *",
                    "allow uri RIPVServer * ?download *",
                    "allow uri DataVisServer * *",
                    "allow ann RIPVServer * ?download *",
                    "allow ann DataVisServer * *",
                    "allow dora DataVisServer * *");
            sys.register(serial("gpc1", one.listen(0), dir.resolve("w1")));
            sys.register(serial("gpc2", two.listen(0), dir.resolve("w2")));
            sys.register(new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis"))));
            String first = "<SerialPortServer>::<gpc1>veh1";
            String second = "<SerialPortServer>::<gpc2>veh1";

            ClientSocketHandler otto = sys.login("otto");
            for (String mb : List.of(first, second)) {
                OutgoingServerMessage r = otto.call(mb, "ymodem:get MISSION1.LOG", Priority.NORMAL, T, null);
                assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
                assertThat(r.footer().replyText()).contains(FileStore.folderFor(mb) + "/MISSION1.LOG");
            }
            String f1 = FileStore.folderFor(first) + "/MISSION1.LOG";
            String f2 = FileStore.folderFor(second) + "/MISSION1.LOG";
            assertThat(f1).isNotEqualTo(f2);
            assertThat(Files.readString(sys.downloadDir().resolve(f1))).isEqualTo("the first glider's log\n");
            assertThat(Files.readString(sys.downloadDir().resolve(f2))).isEqualTo("the second glider's log, longer\n");
            FileListing dl = (FileListing) otto.call("", "?dlfiles", Priority.NORMAL, T, null).footer().result();
            assertThat(dl.files()).extracting(FileListing.Entry::name).contains(f1, f2).noneMatch(n -> n.startsWith("veh1/"));

            // uri may read veh1: its files, yes. ann has the ?download rule but may read no vehicle:
            // the rule follows the MailBox whose folder it is, so neither fetched nor attached.
            ClientSocketHandler uri = sys.login("uri");
            assertThat(uri.call("", "?download " + f1 + " 0 100", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
            ClientSocketHandler ann = sys.login("ann");
            OutgoingServerMessage refused = ann.call("", "?download " + f2 + " 0 100", Priority.NORMAL, T, null);
            assertThat(refused.footer().errorCode()).as(refused.footer().replyText()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(refused.footer().replyText()).contains(second).contains("?read");
            OutgoingServerMessage vis = ann.call("<DataVisServer>::<localhost>TTY1", "vis:file " + f1 + " x=time y=depth",
                    Priority.NORMAL, T, null);
            assertThat(vis.footer().errorCode()).as(vis.footer().replyText()).isEqualTo(ErrorCode.FORBIDDEN);

            // dora has rights on the DataVisServer only: no vehicle's download reaches her through vis:file.
            ClientSocketHandler dora = sys.login("dora");
            for (String f : List.of(f1, f2)) {
                OutgoingServerMessage v = dora.call("<DataVisServer>::<localhost>TTY1", "vis:file " + f + " x=time y=depth",
                        Priority.NORMAL, T, null);
                assertThat(v.footer().errorCode()).as(v.footer().replyText()).isEqualTo(ErrorCode.FORBIDDEN);
                assertThat(v.footer().replyText()).doesNotContain("glider's log");
            }
        }
    }

    private static SerialPortServer serial(String host, int port, Path work) {
        LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + port).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(YmodemConfig.lrzsz());
        return SerialPortServer.withCalls(host, List.of(new VehicleLink(link, CallSettings.defaults().withName("veh1"))),
                null, false, work);
    }
}
