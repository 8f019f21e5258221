package org.ripv.server.workflow;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class WorkflowQueuesTest {
    static final String MB = "<SerialPortServer>::<shore>ru29";
    static final String SOURCE = "workflow every-call\n# a comment with = and : and \\ in it\nsend dir expect='C:\\\\>'\n"
            + "ymodem:get *.DBD\n";

    @TempDir
    Path dir;

    @Test
    void queuesSurviveAReopenWithStateAndOrder() throws Exception {
        WorkflowQueues q = new WorkflowQueues(dir);
        Workflow w = WorkflowParser.parse("fetch.wf", SOURCE, n -> true);
        QueuedWorkflow a = q.add(MB, "alice", SOURCE, w);
        QueuedWorkflow b = q.add(MB, "bob", "send dir\n", WorkflowParser.parse("dir.wf", "send dir\n", n -> true));
        q.add("<SerialPortServer>::<shore>ru30", "alice", SOURCE, w);
        q.update(MB, a.id(), e -> e.with(QueuedWorkflow.State.CUT, 1, "the call ended (DIVED)").withFetched(List.of("A.DBD", "B.DBD")));

        WorkflowQueues again = new WorkflowQueues(dir);
        List<QueuedWorkflow> list = again.list(MB);
        assertThat(list).extracting(QueuedWorkflow::id).containsExactly(a.id(), b.id());
        QueuedWorkflow first = list.get(0);
        assertThat(first.owner()).isEqualTo("alice");
        assertThat(first.source()).isEqualTo(SOURCE);
        assertThat(first.state()).isEqualTo(QueuedWorkflow.State.CUT);
        assertThat(first.nextStep()).isEqualTo(1);
        assertThat(first.lastError()).isEqualTo("the call ended (DIVED)");
        assertThat(first.fetched()).containsExactly("A.DBD", "B.DBD");
        assertThat(first.workflow().mode()).isEqualTo(Workflow.Mode.EVERY_CALL);
        assertThat(first.workflow().steps().get(0).expect().pattern()).isEqualTo("C:\\\\>");
        assertThat(again.mailboxes()).hasSize(2);

        // ids keep counting after a restart: a removed id is never reused
        again.remove(MB, b.id());
        QueuedWorkflow c = again.add(MB, "carol", "send dir\n", WorkflowParser.parse("dir.wf", "send dir\n", n -> true));
        assertThat(c.id()).isGreaterThan(b.id());
        assertThat(new WorkflowQueues(dir).list(MB)).extracting(QueuedWorkflow::id).containsExactly(a.id(), c.id());
    }

    @Test
    void aRunInterruptedByAStopResumesAsCut() throws Exception {
        WorkflowQueues q = new WorkflowQueues(dir);
        QueuedWorkflow a = q.add(MB, "alice", SOURCE, WorkflowParser.parse("f.wf", SOURCE, n -> true));
        q.update(MB, a.id(), e -> e.started().with(QueuedWorkflow.State.PAUSED, 1, ""));
        QueuedWorkflow back = new WorkflowQueues(dir).list(MB).get(0);
        assertThat(back.state()).isEqualTo(QueuedWorkflow.State.CUT);
        assertThat(back.nextStep()).isEqualTo(1);
        assertThat(back.runs()).isEqualTo(1);
    }

    @Test
    void filesAreOwnerOnlyAndWrittenWhole() throws Exception {
        WorkflowQueues q = new WorkflowQueues(dir);
        q.add(MB, "alice", SOURCE, WorkflowParser.parse("f.wf", SOURCE, n -> true));
        try (var s = Files.list(dir)) {
            List<Path> files = s.toList();
            assertThat(files).hasSize(1);
            assertThat(files.get(0).getFileName().toString()).endsWith(".properties").doesNotContain("<").doesNotStartWith(".");
            assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(files.get(0)))).isEqualTo("rw-------");
        }
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(dir))).isEqualTo("rwx------");
    }

    @Test
    void aDamagedQueueFileCostsOnlyItsOwnMailBox() throws Exception {
        WorkflowQueues q = new WorkflowQueues(dir);
        q.add(MB, "alice", SOURCE, WorkflowParser.parse("f.wf", SOURCE, n -> true));
        Files.writeString(dir.resolve("junk.properties"), "mailbox=<X>::<y>z\ncount=1\nentry.0.file=x\n");
        WorkflowQueues again = new WorkflowQueues(dir);
        assertThat(again.list(MB)).hasSize(1);
        assertThat(again.list("<X>::<y>z")).isEmpty();
    }

    @Test
    void aQueueHasALimit() throws Exception {
        WorkflowQueues q = new WorkflowQueues(dir);
        Workflow w = WorkflowParser.parse("d.wf", "send dir", n -> true);
        for (int i = 0; i < WorkflowQueues.MAX_PER_MAILBOX; i++) {
            q.add(MB, "alice", "send dir", w);
        }
        assertThatThrownBy(() -> q.add(MB, "alice", "send dir", w)).hasMessageContaining("remove some first");
    }
}
