package org.ripv.server.workflow;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.server.dataloop.IngestVerdict;

/** The counts a notify may quote, and the counts read back from a download's reply. */
class RunTallyTest {
    @Test
    void aNotifySaysWhatTheRunDidAndNothingElse() {
        List<String> fetched = new ArrayList<>(List.of("ru29/A.DBD"));
        RunTally t = new RunTally(fetched);
        fetched.add("ru29/B.DBD");
        t.ingested(1);
        t.stepFailed();
        assertThat(t.fill("ru29: {fetched} fetched, {ingested} ingested, {failed} failed, {other} kept"))
                .isEqualTo("ru29: 2 fetched, 1 ingested, 1 failed, {other} kept");
        assertThat(t.describe()).isEqualTo("fetched 2, ingested 1, 1 step(s) failed");
    }

    @Test
    void theIngestCountsComeFromTheDataLoopsLastLine() {
        String text = "received X.mrg (10 bytes)\nfetched 9, ingested 9 is what the vehicle printed\n"
                + "fetched 1, ingested 0: not ingested (BAD_REQUEST): X.mrg: refused, nothing stored: line 1";
        IngestVerdict.Counts c = IngestVerdict.counts(text).orElseThrow();
        assertThat(c.fetched()).isEqualTo(1);
        assertThat(c.ingested()).isZero();
        assertThat(c.why()).startsWith("not ingested (BAD_REQUEST): X.mrg");
        assertThat(IngestVerdict.counts("received X.SBD (10 bytes)")).isEmpty();
        assertThat(IngestVerdict.counts("fetched 2, ingested 2 into <DatabaseServer>::<h>TTY1:\nA: 3 rows").orElseThrow().why())
                .isEmpty();
    }
}
