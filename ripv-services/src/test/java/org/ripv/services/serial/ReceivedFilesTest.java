package org.ripv.services.serial;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.exceptions.ServiceException;
import org.ripv.messages.ErrorCode;

/** Received files that would not fit the service's heap in one reply are refused before they are read. */
class ReceivedFilesTest {
    @TempDir
    Path dir;

    @Test
    void aBatchOverTheBudgetIsRefusedWithWhatToDo() throws Exception {
        Path a = Files.write(dir.resolve("A.DBD"), new byte[600]);
        Path b = Files.write(dir.resolve("B.DBD"), new byte[500]);
        ReceivedFiles.checkFits("ymodem:get", List.of(a, b), 1100);
        assertThatThrownBy(() -> ReceivedFiles.checkFits("ymodem:get", List.of(a, b), 1099))
                .isInstanceOfSatisfying(ServiceException.class, e -> assertThat(e.code()).isEqualTo(ErrorCode.TRANSFER_FAILED))
                .hasMessageContaining("1100 bytes in 2 file(s)").hasMessageContaining("1099 bytes: a quarter of its heap")
                .hasMessageContaining("Fetch fewer files at a time");
        assertThat(ReceivedFiles.budget()).isEqualTo(Math.min(Runtime.getRuntime().maxMemory() / 4, org.ripv.rmi.RmiSupport.MAX_RMI_BYTES / 2));
    }

    /**
     * Issue 33 item 9: on an 8 GB heap a quarter is 2 GB, so a 1.5 GB zmodem:get was read whole and
     * sent in a reply RMI cannot carry (the server dropped it; the user never got an answer). Now the
     * budget is at most half of what an RMI reply may carry, and such a file is refused with why.
     */
    @Test
    void aFileRmiCannotCarryIsRefusedOnAnyHeap() throws Exception {
        assertThat(ReceivedFiles.budget(8L << 30)).isEqualTo(org.ripv.rmi.RmiSupport.MAX_RMI_BYTES / 2);
        Path huge = dir.resolve("HUGE.DBD");
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(huge.toFile(), "rw")) {
            f.setLength(1_500L << 20); // sparse: 1.5 GB on paper, no disk
        }
        assertThatThrownBy(() -> ReceivedFiles.checkFits("zmodem:get", List.of(huge), ReceivedFiles.budget(8L << 30)))
                .isInstanceOfSatisfying(ServiceException.class, e -> assertThat(e.code()).isEqualTo(ErrorCode.TRANSFER_FAILED))
                .hasMessageContaining("a single file this large cannot come through RIPV in one piece");
    }
}
