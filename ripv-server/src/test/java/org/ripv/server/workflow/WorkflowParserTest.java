package org.ripv.server.workflow;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Set;
import java.util.function.Predicate;
import org.junit.jupiter.api.Test;

class WorkflowParserTest {
    static final Predicate<String> UPLOADS = Set.of("mission.mi", "goto_l10.ma")::contains;

    static Workflow parse(String text) {
        return WorkflowParser.parse("w.wf", text, UPLOADS);
    }

    @Test
    void zmodemStepsAreTransfersThatSendZmodemCommands() {
        Workflow w = parse("""
                zmodem:get *.DBD 01230000.SBD all
                zmodem:put goto_l10.ma continue-on-error
                ymodem:get A.LOG
                """);
        assertThat(w.steps()).extracting(Step::kind).containsExactly(Step.Kind.GET, Step.Kind.PUT, Step.Kind.GET);
        assertThat(w.steps()).extracting(Step::transferWord).containsExactly("zmodem:get", "zmodem:put", "ymodem:get");
        assertThat(w.steps().get(0).describe()).isEqualTo("zmodem:get *.DBD 01230000.SBD all");
        assertThat(w.steps().get(0).timeout()).isEqualTo(w.steps().get(2).timeout());
        assertThatThrownBy(() -> parse("zmodem:put nosuch.ma")).hasMessageContaining("zmodem:put nosuch.ma: no such file");
        assertThatThrownBy(() -> parse("zmodem:get")).hasMessageContaining("zmodem:get needs file names");
        assertThatThrownBy(() -> parse("send zmodem:get A")).hasMessageContaining("zmodem:get and zmodem:put steps");
    }

    @Test
    void everyKindOfStepWithOptions() {
        Workflow w = parse("""
                # morning call
                workflow every-call
                send dir expect=MISSION fail='Bad command' timeout=30s
                ymodem:get *.DBD *.SBD          # only new ones
                ymodem:get GLIDER.CFG all continue-on-error
                ymodem:put mission.mi timeout=5m
                wait-for "Glider .* at surface" timeout=90
                ingest to=<DatabaseServer>::<shore>TTY1
                vis vis:track to=<DataVisServer>::<shore>TTY1
                notify "logs fetched, mission sent"
                send "put c_dive_target_depth 30" expect="c_dive_target_depth.*30"
                """);
        assertThat(w.mode()).isEqualTo(Workflow.Mode.EVERY_CALL);
        assertThat(w.steps()).extracting(Step::kind).containsExactly(Step.Kind.SEND, Step.Kind.GET, Step.Kind.GET,
                Step.Kind.PUT, Step.Kind.WAIT_FOR, Step.Kind.INGEST, Step.Kind.VIS, Step.Kind.NOTIFY, Step.Kind.SEND);
        Step send = w.steps().get(0);
        assertThat(send.line()).isEqualTo(3);
        assertThat(send.text()).isEqualTo("dir");
        assertThat(send.expect().pattern()).isEqualTo("MISSION");
        assertThat(send.fail().pattern()).isEqualTo("Bad command");
        assertThat(send.timeout()).isEqualTo(Duration.ofSeconds(30));
        assertThat(w.steps().get(1).names()).containsExactly("*.DBD", "*.SBD");
        assertThat(w.steps().get(1).all()).isFalse();
        assertThat(w.steps().get(2).all()).isTrue();
        assertThat(w.steps().get(2).continueOnError()).isTrue();
        assertThat(w.steps().get(3).timeout()).isEqualTo(Duration.ofMinutes(5));
        assertThat(w.steps().get(4).text()).isEqualTo("Glider .* at surface");
        assertThat(w.steps().get(4).timeout()).isEqualTo(Duration.ofSeconds(90));
        assertThat(w.steps().get(5).to()).isEqualTo("<DatabaseServer>::<shore>TTY1");
        assertThat(w.steps().get(6).text()).isEqualTo("vis:track");
        assertThat(w.steps().get(7).text()).isEqualTo("logs fetched, mission sent");
        assertThat(w.steps().get(8).text()).isEqualTo("put c_dive_target_depth 30");
        assertThat(w.steps().get(8).expect().matcher("c_dive_target_depth(m) 30").find()).isTrue();
    }

    @Test
    void defaultsToOnceWithDefaultTimeouts() {
        Workflow w = parse("send dir\nymodem:get A.LOG\nwait-for x");
        assertThat(w.mode()).isEqualTo(Workflow.Mode.ONCE);
        assertThat(w.steps().get(0).timeout()).isEqualTo(WorkflowParser.SEND_TIMEOUT);
        assertThat(w.steps().get(1).timeout()).isEqualTo(WorkflowParser.TRANSFER_TIMEOUT);
        assertThat(w.steps().get(2).timeout()).isEqualTo(WorkflowParser.WAIT_TIMEOUT);
    }

    @Test
    void quotingRules() {
        assertThat(WorkflowParser.words("a 'b c' \"d \\\" e\" f#g # comment")).containsExactly("a", "b c", "d \" e", "f#g");
        // single quotes keep backslashes for regexes; double quotes keep them too, except before a quote
        assertThat(WorkflowParser.words("wait-for 'C:\\\\>' expect=\"\\d+ bytes\"")).containsExactly("wait-for", "C:\\\\>",
                "expect=\\d+ bytes");
        assertThat(parse("wait-for 'C:\\\\>'").steps().get(0).text()).isEqualTo("C:\\\\>");
        assertThat(parse("wait-for 'C:\\\\>'").steps().get(0).text()).matches(s -> java.util.regex.Pattern.compile(s)
                .matcher("C:\\>").find());
        assertThat(WorkflowParser.words("   # only a comment")).isEmpty();
        assertThat(WorkflowParser.words("x ''")).containsExactly("x", "");
    }

    @Test
    void refusalsNameTheLineAndTheReason() {
        assertRefused("send dir\nfrobnicate now", 2, "unknown step 'frobnicate'");
        assertRefused("\n\nsend dir expect=(unclosed", 3, "bad expect regex '(unclosed'");
        assertRefused("wait-for '[a-'", 1, "bad wait-for regex");
        assertRefused("ymodem:put missing.mi", 1, "no such file in the upload store");
        assertRefused("send dir timeout=soon", 1, "bad timeout 'soon'");
        assertRefused("send dir timeout=3h", 1, "out of range");
        assertRefused("send \"dir", 1, "not closed");
        assertRefused("send dir expect=x extra", 1, "after the options");
        assertRefused("workflow sometimes", 1, "unknown mode 'sometimes'");
        assertRefused("workflow once\nworkflow once\nsend dir", 2, "a second 'workflow' line");
        assertRefused("vis vis:track", 1, "vis needs to=MAILBOX");
        assertRefused("ingest", 1, "ingest needs to=MAILBOX");
        assertRefused("ymodem:get ../etc/passwd", 1, "is not a file name");
        assertRefused("send ymodem:get x", 1, "use the ymodem:get and ymodem:put steps");
        assertRefused("send ?lock x", 1, "? commands are not steps");
        assertRefused("send dir to=<X>::<y>z", 1, "to= belongs to ingest and vis");
        assertRefused("ymodem:put mission.mi goto_l10.ma", 1, "one uploaded file");
        assertRefused("# nothing\n\n", 0, "no steps");
        assertRefused("send dir\0", 1, "NUL");
    }

    private static void assertRefused(String text, int line, String reason) {
        assertThatThrownBy(() -> parse(text)).isInstanceOf(WorkflowException.class)
                .hasMessageContaining(reason)
                .hasMessageStartingWith(line > 0 ? "w.wf:" + line + ": " : "w.wf: ")
                .satisfies(e -> assertThat(((WorkflowException) e).line()).isEqualTo(line));
    }

    @Test
    void aThousandStepsWorkAndMoreThanTheLimitIsRefused() {
        StringBuilder b = new StringBuilder("workflow once\n");
        for (int i = 0; i < 1000; i++) {
            b.append(i % 2 == 0 ? "send \"report ++ m_battery\" expect='m_battery' timeout=10s\n" : "ymodem:get *.DBD\n");
        }
        Workflow w = parse(b.toString());
        assertThat(w.steps()).hasSize(1000);
        assertThat(w.steps().get(999).line()).isEqualTo(1001);

        StringBuilder big = new StringBuilder();
        for (int i = 0; i <= WorkflowParser.MAX_STEPS; i++) {
            big.append("send x\n");
        }
        assertRefused(big.toString(), WorkflowParser.MAX_STEPS + 1, "more than " + WorkflowParser.MAX_STEPS + " steps");
    }

    @Test
    void theShippedSamplesParse() throws IOException {
        Path samples = Path.of("..", "docs", "samples");
        for (String name : new String[] {"ru29-every-call.wf", "ru29-new-mission.wf"}) {
            Path f = samples.resolve(name);
            Workflow w = WorkflowParser.parse(name, Files.readString(f), n -> true);
            assertThat(w.steps()).as(name).isNotEmpty();
        }
    }
}
