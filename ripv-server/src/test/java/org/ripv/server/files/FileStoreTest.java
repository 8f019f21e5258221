package org.ripv.server.files;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class FileStoreTest {
    @TempDir
    Path dir;

    @Test
    void chunksMustContinueWhereTheLastEndedAndTheFileAppearsOnlyWhenWhole() throws Exception {
        FileStore s = new FileStore(dir.resolve("up"), dir.resolve("down"), 100);
        assertThat(s.uploadChunk("100001", "a.bin", 0, 10, new byte[4]).complete()).isFalse();
        assertThat(Files.exists(s.uploadDir().resolve("a.bin"))).isFalse();
        assertThat(s.listUploads().files()).isEmpty();
        assertThatThrownBy(() -> s.uploadChunk("100001", "a.bin", 5, 10, new byte[5])).hasMessageContaining("expected offset 4");
        assertThat(s.uploadChunk("100001", "a.bin", 4, 10, new byte[6]).complete()).isTrue();
        assertThat(Files.size(s.uploadDir().resolve("a.bin"))).isEqualTo(10);
        assertThat(s.listUploads().files()).extracting(e -> e.name()).containsExactly("a.bin");
    }

    @Test
    void aClientThatLeavesLeavesNothingBehind() throws Exception {
        FileStore s = new FileStore(dir.resolve("up"), dir.resolve("down"), 100);
        s.uploadChunk("100002", "half.bin", 0, 10, new byte[5]);
        s.abortAll("100002");
        try (var files = Files.list(s.uploadDir().resolve(".partial"))) {
            assertThat(files).isEmpty();
        }
    }

    @Test
    void fileNamesFollowTheCgiRules() {
        for (String bad : new String[] {"../x", "..\\x", "/etc/passwd", ".hidden", "a\0b", "a".repeat(256), "", "c:evil"}) {
            assertThatThrownBy(() -> FileNames.check(bad)).as(bad).isInstanceOf(IllegalArgumentException.class);
        }
        assertThat(FileNames.check("mission-01.log")).isEqualTo("mission-01.log");
        assertThat(FileNames.check("a".repeat(255))).hasSize(255);
    }

    @Test
    void downloadsAreReadInBoundedChunks() throws Exception {
        FileStore s = new FileStore(dir.resolve("up"), dir.resolve("down"), 100);
        assertThat(s.storeDownload("ttyV0", "log.txt", "0123456789".getBytes())).isEqualTo("ttyV0/log.txt");
        DownloadChunk chunk = s.readDownload("ttyV0/log.txt", 4, 3);
        assertThat(chunk.total()).isEqualTo(10);
        assertThat(new String(chunk.data())).isEqualTo("456");
        assertThatThrownBy(() -> s.readDownload("log.txt", 11, 3)).hasMessageContaining("outside");
        assertThatThrownBy(() -> s.readDownload("missing", 0, 3)).hasMessageContaining("no file 'missing'");
    }

    @Test
    void eachMailBoxsDownloadsLiveApartAndPlainNamesFindTheOnlyOne() throws Exception {
        FileStore s = new FileStore(dir.resolve("up"), dir.resolve("down"), 100);
        s.storeDownload("ttyV0", "MISSION1.LOG", "zero".getBytes());
        s.storeDownload("ttyV1", "MISSION1.LOG", "one".getBytes());
        s.storeDownload("ttyV1", "ONLY.LOG", "only".getBytes());
        assertThat(new String(s.readDownload("ttyV0/MISSION1.LOG", 0, 100).data())).isEqualTo("zero");
        assertThat(new String(s.readDownload("ttyV1/MISSION1.LOG", 0, 100).data())).isEqualTo("one");
        assertThat(new String(s.readDownload("ONLY.LOG", 0, 100).data())).isEqualTo("only");
        assertThatThrownBy(() -> s.readDownload("MISSION1.LOG", 0, 100)).hasMessageContaining("ttyV0/MISSION1.LOG, ttyV1/MISSION1.LOG");
        assertThat(s.listDownloads().files()).extracting(e -> e.name())
                .containsExactly("ttyV0/MISSION1.LOG", "ttyV1/MISSION1.LOG", "ttyV1/ONLY.LOG");
        for (String bad : new String[] {"../up/x", "ttyV0/../../x", "ttyV0/a/b", ".partial/x", "/etc/passwd", "ttyV0/.x"}) {
            assertThatThrownBy(() -> s.readDownload(bad, 0, 1)).as(bad).isInstanceOf(IllegalArgumentException.class);
        }
        assertThat(FileStore.folderName("../x y")).isEqualTo("_._x_y");
        assertThatThrownBy(() -> s.storeDownload("ttyV0", "../x", new byte[1])).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void anUploadNeverReplacesSilently() throws Exception {
        FileStore s = new FileStore(dir.resolve("up"), dir.resolve("down"), 100);
        s.uploadChunk("1", "alice", "m.bin", 0, 3, "one".getBytes(), UploadMode.REFUSE, 1000);
        assertThatThrownBy(() -> s.uploadChunk("2", "bob", "m.bin", 0, 3, "two".getBytes(), UploadMode.REFUSE, 1000))
                .isInstanceOf(FileExistsException.class);
        // taken while the upload was under way: still refused at the end
        s.uploadChunk("2", "bob", "late.bin", 0, 4, "tw".getBytes(), UploadMode.REFUSE, 1000);
        s.uploadChunk("3", "carol", "late.bin", 0, 1, "x".getBytes(), UploadMode.REFUSE, 1000);
        assertThatThrownBy(() -> s.uploadChunk("2", "bob", "late.bin", 2, 4, "wo".getBytes(), UploadMode.REFUSE, 1000))
                .isInstanceOf(FileExistsException.class);
        assertThat(Files.readString(s.uploadDir().resolve("late.bin"))).isEqualTo("x");
        FileStore.ChunkResult kept = s.uploadChunk("2", "bob", "m.bin", 0, 3, "two".getBytes(), UploadMode.KEEP, 1000);
        assertThat(kept.storedAs()).isEqualTo("m(1).bin");
        assertThat(s.uploadChunk("2", "bob", "m.bin", 0, 5, "three".getBytes(), UploadMode.KEEP, 1000).storedAs()).isEqualTo("m(2).bin");
        assertThat(Files.readString(s.uploadDir().resolve("m.bin"))).isEqualTo("one");
        s.uploadChunk("2", "bob", "m.bin", 0, 4, "four".getBytes(), UploadMode.REPLACE, 1000);
        assertThat(Files.readString(s.uploadDir().resolve("m.bin"))).isEqualTo("four");
        assertThat(s.owner("m.bin")).isEqualTo("bob");
        assertThat(FileStore.numbered("README", 3)).isEqualTo("README(3)");
    }

    @Test
    void quotaCountsWhatAUserHoldsAndDeleteFreesIt() throws Exception {
        FileStore s = new FileStore(dir.resolve("up"), dir.resolve("down"), 100);
        s.uploadChunk("1", "alice", "a.bin", 0, 60, new byte[60], UploadMode.REFUSE, 100);
        assertThatThrownBy(() -> s.uploadChunk("1", "alice", "b.bin", 0, 50, new byte[50], UploadMode.REFUSE, 100))
                .isInstanceOf(FileTooLargeException.class).hasMessageContaining("quota");
        s.uploadChunk("2", "bob", "b.bin", 0, 50, new byte[50], UploadMode.REFUSE, 100); // bob has his own
        assertThat(s.usage("alice")).isEqualTo(60);
        assertThat(s.delete("a.bin")).isEqualTo("upload directory");
        assertThat(s.usage("alice")).isZero();
        s.uploadChunk("1", "alice", "b2.bin", 0, 90, new byte[90], UploadMode.REFUSE, 100);
        // the owners survive a restart
        FileStore again = new FileStore(dir.resolve("up"), dir.resolve("down"), 100);
        assertThat(again.usage("alice")).isEqualTo(90);
        s.storeDownload("ttyV0", "x.log", new byte[1]);
        assertThat(s.delete("ttyV0/x.log")).isEqualTo("download directory");
        assertThatThrownBy(() -> s.delete("ttyV0/x.log")).isInstanceOf(java.nio.file.NoSuchFileException.class);
        assertThatThrownBy(() -> s.delete("../permit.txt")).isInstanceOf(IllegalArgumentException.class);
    }

    @Test
    void directoriesAndFilesAreOwnerOnly() throws Exception {
        FileStore s = new FileStore(dir.resolve("up"), dir.resolve("down"), 100);
        s.uploadChunk("1", "alice", "a.bin", 0, 3, new byte[3], UploadMode.REFUSE, 100);
        s.storeDownload("ttyV0", "x.log", new byte[1]);
        for (java.nio.file.Path p : java.util.List.of(s.uploadDir(), s.downloadDir(), s.downloadDir().resolve("ttyV0"))) {
            assertThat(java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(p))).as(p.toString())
                    .isEqualTo("rwx------");
        }
        for (java.nio.file.Path p : java.util.List.of(s.uploadDir().resolve("a.bin"), s.downloadDir().resolve("ttyV0/x.log"),
                s.uploadDir().resolve(".owners"))) {
            assertThat(java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(p))).as(p.toString())
                    .isEqualTo("rw-------");
        }
    }

    @Test
    void aFolderIsUniqueToTheWholeAddressAndAnOldHandleFolderIsMovedToItsMailBox() throws Exception {
        // Issue 23, item 4: download/veh1/ was shared by <SerialPortServer>::<gpc1>veh1 and ::<gpc2>veh1.
        String a = "<SerialPortServer>::<gpc1>veh1";
        String b = "<SerialPortServer>::<gpc2>veh1";
        assertThat(FileStore.folderFor(a)).isEqualTo("veh1@gpc1@SerialPortServer");
        assertThat(FileStore.folderFor(b)).isNotEqualTo(FileStore.folderFor(a));
        assertThat(FileStore.folderFor("<DataVisServer>::<gpc1>veh1")).isNotEqualTo(FileStore.folderFor(a));
        // Names that had to be changed carry a hash of the address, so they stay apart.
        assertThat(FileStore.folderFor("<SerialPortServer>::<h>a b")).isNotEqualTo(FileStore.folderFor("<SerialPortServer>::<h>a_b"));
        assertThat(FileStore.folderFor("<SerialPortServer>::<" + "h".repeat(80) + ">x")).hasSizeLessThanOrEqualTo(64);

        Path down = dir.resolve("down");
        Files.createDirectories(down.resolve("veh1"));
        Files.writeString(down.resolve("veh1/OLD.LOG"), "from before");
        FileStore s = new FileStore(dir.resolve("up"), down, 100);
        s.adopt(a);
        assertThat(down.resolve("veh1")).doesNotExist();
        String old = FileStore.folderFor(a) + "/OLD.LOG";
        assertThat(Files.readString(down.resolve(old))).isEqualTo("from before");
        assertThat(s.mailboxOf(old)).contains(a);
        assertThat(s.mailboxOf("OLD.LOG")).contains(a);
        assertThat(s.storeDownload(b, "OLD.LOG", "second".getBytes())).isEqualTo(FileStore.folderFor(b) + "/OLD.LOG");
        assertThat(Files.readString(down.resolve(old))).as("the other vehicle's file is untouched").isEqualTo("from before");
        assertThat(s.mailboxOf(FileStore.folderFor(b) + "/OLD.LOG")).contains(b);
        assertThat(s.listDownloads().files()).extracting(e -> e.name()).noneMatch(n -> n.contains(".mailbox"));
    }
}
