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
                .hasMessageContaining("1100 bytes in 2 file(s)").hasMessageContaining("1099 bytes, a quarter of its heap")
                .hasMessageContaining("fetch fewer files at a time");
        assertThat(ReceivedFiles.budget()).isEqualTo(Runtime.getRuntime().maxMemory() / 4);
    }
}
