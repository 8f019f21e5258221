package org.ripv.server.workflow;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.server.files.FileStore;

/** Each call's list of what the vehicle sent: the files its download folder received during the call, once. */
class CallArrivalsTest {
    static final String MAILBOX = "<SerialPortServer>::<glider-pc>ru29";

    @TempDir
    Path dir;

    @Test
    void theFilesOfTheCallAreListedWhenItEndsAndOnlyOnce() throws Exception {
        FileStore files = new FileStore(dir.resolve("up"), dir.resolve("down"), 1000);
        String folder = FileStore.folderFor(MAILBOX);
        CallArrivals arrivals = new CallArrivals();
        assertThat(arrivals.ended(MAILBOX, files)).as("no call began").isNull();
        arrivals.surfaced(MAILBOX);
        assertThat(arrivals.ended(MAILBOX, files)).as("a call that brought nothing").isNull();

        arrivals.surfaced(MAILBOX);
        files.storeDownload(MAILBOX, "01230000.DBD", new byte[300]);
        files.storeDownload(MAILBOX, "NIGHT.MI", new byte[42]);
        assertThat(arrivals.ended(MAILBOX, files)).isEqualTo("from-vehicle: this call brought 2 file(s): " + folder
                + "/01230000.DBD (300 bytes), " + folder + "/NIGHT.MI (42 bytes)");
        assertThat(arrivals.ended(MAILBOX, files)).as("listed once").isNull();
    }
}
