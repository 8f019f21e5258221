package org.ripv.files;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PrivateFilesTest {
    @TempDir
    Path dir;

    @Test
    void aFolderOfItsOwnBecomesOwnerOnly() throws IOException {
        assumeTrue(Files.getFileStore(dir).supportsFileAttributeView("posix"), "a POSIX file system");
        Path data = dir.resolve("data");
        Files.createDirectory(data, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwxr-xr-x")));
        PrivateFiles.restrict(data);
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(data))).isEqualTo("rwx------");
    }

    @Test
    void aSharedStickyFolderLikeTmpIsRefusedAndLeftAsItWas() throws IOException {
        assumeTrue(Files.getFileStore(dir).supportsFileAttributeView("unix"), "the unix attribute view");
        Path shared = dir.resolve("shared");
        Files.createDirectory(shared);
        Files.setAttribute(shared, "unix:mode", 01777);
        assertThatThrownBy(() -> PrivateFiles.restrict(shared))
                .isInstanceOf(IOException.class)
                .hasMessageContaining("shared directory")
                .hasMessageContaining("a folder of its own");
        assertThat(((Integer) Files.getAttribute(shared, "unix:mode")) & 07777).isEqualTo(01777);
    }

    @Test
    void replaceSwapsTheWholeTextInOwnerOnlyAndLeavesNoTemporaryFile() throws IOException {
        assumeTrue(Files.getFileStore(dir).supportsFileAttributeView("posix"), "a POSIX file system");
        Path f = dir.resolve("queue.json");
        Files.writeString(f, "old text that is longer than the new");
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-r--r--"));
        PrivateFiles.replace(f, "new");
        assertThat(Files.readString(f)).isEqualTo("new");
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(f))).isEqualTo("rw-------");
        try (var left = Files.list(dir)) {
            assertThat(left).containsExactly(f);
        }
    }
}
