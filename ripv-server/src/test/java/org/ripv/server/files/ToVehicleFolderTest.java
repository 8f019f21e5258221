package org.ripv.server.files;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The to-vehicle folders of the upload store: names that stay inside, files that move to sent/ whole with a receipt. */
class ToVehicleFolderTest {
    static final String MAILBOX = "<SerialPortServer>::<glider-pc>ru29";

    @TempDir
    Path dir;

    @Test
    void onlyToVehicleFolderNameIsAcceptedAndEveryPartIsPlain() {
        String f = FileStore.folderFor(MAILBOX);
        assertThat(ToVehicleFolder.parse("to-vehicle/" + f + "/goto_l10.ma")).isEqualTo(new ToVehicleFolder.Name(f, "goto_l10.ma"));
        for (String bad : new String[] {"to-vehicle/../x", "to-vehicle/" + f + "/../x", "to-vehicle/" + f + "/a/b",
                "to-vehicle/" + f + "/.hidden", "to-vehicle//x", "to-vehicle/" + f + "/", "to-vehicle/" + f + "/sent"}) {
            assertThatThrownBy(() -> ToVehicleFolder.parse(bad)).as(bad).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("'" + bad + "'");
        }
        assertThat(ToVehicleFolder.isToVehicle("a/b")).isFalse();
    }

    @Test
    void anUploadLandsInTheFolderOwnerOnlyAndMovesToSentWithItsReceipt() throws Exception {
        FileStore s = new FileStore(dir.resolve("up"), dir.resolve("down"), 1000);
        s.adopt(MAILBOX);
        String f = FileStore.folderFor(MAILBOX);
        assertThat(s.isMailboxFolder(f)).isTrue();
        assertThat(s.isMailboxFolder("nobody@nowhere@None")).isFalse();
        String name = "to-vehicle/" + f + "/goto_l10.ma";
        byte[] data = "behavior_name=goto_list\n".getBytes(StandardCharsets.US_ASCII);
        assertThat(s.uploadChunk("c1", "alice", name, 0, data.length, data, UploadMode.REFUSE, 1000).complete()).isTrue();
        Path stored = s.uploadDir().resolve("to-vehicle").resolve(f).resolve("goto_l10.ma");
        assertThat(stored).hasBinaryContent(data);
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(stored))).isEqualTo("rw-------");
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(stored.getParent()))).isEqualTo("rwx------");
        assertThat(s.owner(name)).isEqualTo("alice");
        assertThat(s.usage("alice")).isEqualTo(data.length);
        assertThat(s.listUploads().files()).extracting(e -> e.name()).containsExactly(name);
        assertThat(s.toVehiclePending(MAILBOX)).containsExactly(name);
        // a taken name is refused as any upload's is
        assertThatThrownBy(() -> s.uploadChunk("c2", "alice", name, 0, data.length, data, UploadMode.REFUSE, 1000))
                .isInstanceOf(FileExistsException.class);

        assertThat(s.toVehicleSent(name, "receipt one\n")).isEqualTo("to-vehicle/" + f + "/sent/goto_l10.ma");
        Path sent = stored.getParent().resolve("sent");
        assertThat(stored).doesNotExist();
        assertThat(sent.resolve("goto_l10.ma")).hasBinaryContent(data);
        assertThat(sent.resolve("goto_l10.ma.receipt")).hasContent("receipt one");
        assertThat(s.toVehiclePending(MAILBOX)).isEmpty();
        assertThat(s.usage("alice")).as("a sent file leaves the quota: ?delete cannot reach sent/").isZero();

        // the same name again: the earlier sent file and its receipt are kept
        s.uploadChunk("c3", "alice", name, 0, data.length, data, UploadMode.REFUSE, 1000);
        assertThat(s.toVehicleSent(name, "receipt two\n")).isEqualTo("to-vehicle/" + f + "/sent/goto_l10(1).ma");
        assertThat(sent.resolve("goto_l10.ma.receipt")).hasContent("receipt one");
        assertThat(sent.resolve("goto_l10(1).ma.receipt")).hasContent("receipt two");

        s.uploadChunk("c4", "alice", name, 0, data.length, data, UploadMode.REFUSE, 1000);
        assertThat(s.delete(name)).isEqualTo("to-vehicle folder");
        assertThat(s.toVehiclePending(MAILBOX)).isEmpty();
    }
}
