package org.ripv.server.workflow;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ReceiptsTest {
    static final String MB = "<SerialPortServer>::<shore>ru29";

    @TempDir
    Path dir;

    @Test
    void receiptsRenderTheirStepsAndTheLastNComeBackOldestFirst() throws Exception {
        Receipts receipts = new Receipts(dir);
        for (int run = 1; run <= 3; run++) {
            Receipt r = new Receipt(MB, 7, "fetch.wf", "alice", run, run == 3 ? 1 : 0);
            r.steps.add(new Receipt.StepRecord(0, 2, 3, "ymodem:get *.SBD", 1000, 2500, "OK", "received A.SBD",
                    List.of(new Receipt.FileRecord("A.SBD", 12, "ab".repeat(32))), ""));
            r.steps.add(new Receipt.StepRecord(1, 2, 4, "send GO", 2500, 2600, "FAILED", Receipt.cut("x".repeat(5000)), List.of(),
                    "the reply did not match expect=submerging"));
            r.result = "FAILED";
            r.ended = r.started + 1600;
            receipts.write(r);
            Thread.sleep(2); // distinct start times
        }
        List<String> last = receipts.last(MB, 2);
        assertThat(last).hasSize(2);
        assertThat(last.get(0)).contains("run 2").doesNotContain("resumed");
        assertThat(last.get(1)).contains("receipt: workflow 7 'fetch.wf' of alice on " + MB + ", run 3")
                .contains("(resumed at step 2)")
                .contains("step 1/2 (line 3) ymodem:get *.SBD: OK in 1.5 s")
                .contains("  file A.SBD 12 bytes sha256 " + "ab".repeat(32))
                .contains("step 2/2 (line 4) send GO: FAILED in 0.1 s")
                .contains("  error: the reply did not match expect=submerging")
                .contains("(5000 characters, cut)")
                .contains("result: FAILED at");
        assertThat(receipts.last("<X>::<y>z", 5)).isEmpty();
    }

    @Test
    void controlCharactersFromAWorkflowAreStoredEscaped() throws Exception {
        Receipts receipts = new Receipts(dir);
        Receipt r = new Receipt(MB, 8, "evil.wf", "mallory", 1, 0);
        r.steps.add(new Receipt.StepRecord(0, 1, 2, "notify", 1000, 1100, "OK", "\u001b]0;pwned\u0007\u001b[2J\u009b31mred\rfake",
                List.of(), ""));
        r.result = "DONE";
        receipts.write(r);
        Path d = dir.resolve(org.ripv.server.store.DataFiles.key(MB));
        String stored;
        try (var files = Files.list(d)) {
            stored = Files.readString(files.findFirst().orElseThrow());
        }
        assertThat(stored).doesNotContain("\u001b", "\u0007", "\u009b", "\r")
                .contains("^[]0;pwned^G^[[2J\\u009b31mred\\rfake").contains("\n");
    }

    @Test
    void onlyTheNewestAreKept() throws Exception {
        Receipts receipts = new Receipts(dir);
        Path d = dir.resolve(org.ripv.server.store.DataFiles.key(MB));
        Files.createDirectories(d);
        for (int i = 0; i < Receipts.KEEP + 5; i++) {
            Files.writeString(d.resolve(String.format("%013d-1-%d.txt", i, i)), "old " + i);
        }
        receipts.write(new Receipt(MB, 1, "w.wf", "alice", 1, 0));
        try (var s = Files.list(d)) {
            assertThat(s.count()).isEqualTo(Receipts.KEEP);
        }
        assertThat(d.resolve(String.format("%013d-1-%d.txt", 0, 0))).doesNotExist();
        assertThat(receipts.last(MB, 1).get(0)).contains("receipt: workflow 1 'w.wf'");
    }
}
