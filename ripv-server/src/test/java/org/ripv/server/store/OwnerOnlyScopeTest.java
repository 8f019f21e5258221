package org.ripv.server.store;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.server.workflow.WorkflowQueues;

/** Making RIPV's files owner-only stays inside RIPV's folders: never a parent, never a shared /tmp. */
class OwnerOnlyScopeTest {
    @TempDir
    Path dir;

    @Test
    void aQueueFolderGivenAloneLeavesItsParentAndItsNeighboursAlone() throws IOException {
        assumeTrue(Files.getFileStore(dir).supportsFileAttributeView("posix"), "a POSIX file system");
        Path neighbour = Files.writeString(dir.resolve("someone-elses-script"), "#!/bin/sh\n");
        Files.setPosixFilePermissions(neighbour, PosixFilePermissions.fromString("rwxr-xr-x"));
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        Path queues = Files.createDirectory(dir.resolve("queues"));

        new WorkflowQueues(queues);

        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(neighbour))).isEqualTo("rwxr-xr-x");
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(dir))).isEqualTo("rwxr-xr-x");
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(queues))).isEqualTo("rwx------");
    }

    @Test
    void aSharedStickyFolderIsNeverWalked() throws IOException {
        assumeTrue(Files.getFileStore(dir).supportsFileAttributeView("unix"), "the unix attribute view");
        Path shared = Files.createDirectory(dir.resolve("shared"));
        Files.setAttribute(shared, "unix:mode", 01777);
        Path theirs = Files.writeString(shared.resolve("theirs"), "x");
        Files.setPosixFilePermissions(theirs, PosixFilePermissions.fromString("rw-r--r--"));

        DataFiles.tighten(shared);

        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(theirs))).isEqualTo("rw-r--r--");
    }
}
