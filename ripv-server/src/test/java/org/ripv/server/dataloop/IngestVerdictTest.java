package org.ripv.server.dataloop;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;

/** A download's verdict is the transfer's: files the ingest refused or had already are notes, the reply stays OK. */
class IngestVerdictTest {
    static final OutgoingServerMessage FETCHED = new OutgoingServerMessage(
            Header.request(7, "<SerialPortServer>::<h>ru29", "ymodem:get a.sbd b.scd c.sbd", Priority.NORMAL),
            Footer.ok(Ids.SID_SERIAL, "received a.sbd (10 bytes)\nreceived b.scd (5 bytes)\nreceived c.sbd (9 bytes)", null));

    @Test
    void refusedAndRepeatedFilesAreNotesOfAnOkDownload() {
        String ingest = "a: 376 rows, 9 sensors, 900 values, 3 positions (the file ends after 377 cycles without its end tag 'X')\n"
                + "b.scd: refused, nothing stored: b.scd: byte 0: not a Slocum binary file\n"
                + "c: stored already (file 5), nothing added";
        OutgoingServerMessage v = IngestVerdict.ingested(FETCHED, 3, 3, "<DatabaseServer>::<h>TTY1", ingest);
        assertThat(v.status()).isEqualTo(Status.OK);
        assertThat(v.footer().errorCode()).isNotEqualTo(org.ripv.messages.ErrorCode.DATABASE_ERROR);
        assertThat(v.footer().replyText()).startsWith("received a.sbd")
                .contains("fetched 3, ingested 1 into <DatabaseServer>::<h>TTY1 (2 not ingested, see the notes;")
                .contains("\na: 376 rows")
                .contains("\nnote: b.scd: refused, nothing stored")
                .contains("\nnote: c: stored already (file 5), nothing added");
        assertThat(IngestVerdict.counts(v.footer().replyText()).orElseThrow().ingested()).isEqualTo(1);
    }

    @Test
    void anIngestThatCouldNotRunIsANoteToo() {
        OutgoingServerMessage v = IngestVerdict.notIngested(FETCHED, 3, "not ingested: no DatabaseServer is registered");
        assertThat(v.status()).isEqualTo(Status.OK);
        assertThat(v.footer().replyText()).endsWith("fetched 3, ingested 0: note: not ingested: no DatabaseServer is registered");
    }
}
