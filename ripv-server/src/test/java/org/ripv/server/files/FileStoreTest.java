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
        s.storeDownload("log.txt", "0123456789".getBytes());
        Object[] chunk = s.readDownload("log.txt", 4, 3);
        assertThat((Long) chunk[0]).isEqualTo(10);
        assertThat(new String((byte[]) chunk[1])).isEqualTo("456");
        assertThatThrownBy(() -> s.readDownload("log.txt", 11, 3)).hasMessageContaining("outside");
        assertThatThrownBy(() -> s.readDownload("missing", 0, 3)).hasMessageContaining("no file 'missing'");
    }
}
