package org.ripv.server.workflow;

import static org.assertj.core.api.Assertions.assertThat;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;

/** A workflow file is hostile input: whatever it holds, the parser answers a workflow or a WorkflowException. */
class WorkflowParserProperties {

    @Property(tries = 2000)
    void anyTextParsesOrIsRefusedWithALine(@ForAll("workflowish") String text) {
        try {
            Workflow w = WorkflowParser.parse("f.wf", text, n -> n.startsWith("m"));
            assertThat(w.steps()).isNotEmpty();
            w.steps().forEach(s -> assertThat(s.line()).isPositive());
        } catch (WorkflowException e) {
            assertThat(e.getMessage()).startsWith("f.wf");
            assertThat(e.line()).isBetween(0, text.split("\r\n|\r|\n", -1).length);
        }
    }

    @Provide
    Arbitrary<String> workflowish() {
        Arbitrary<String> words = Arbitraries.of("send", "ymodem:get", "ymodem:put", "wait-for", "ingest", "vis", "notify",
                "workflow", "once", "every-call", "expect=", "fail=", "timeout=", "to=<A>::<b>c", "continue-on-error", "all",
                "\"", "'", "#", "\\", "(", "[", "*", "?", "..", "/", "m.bin", "x.wf", "30s", "0", "9999h", " ", "\t", "\n",
                "\r\n", "\0", "é", "dir");
        Arbitrary<String> junk = Arbitraries.strings().ofMaxLength(20);
        return Arbitraries.oneOf(words, words, words, junk).list().ofMaxSize(40).map(l -> String.join("", l));
    }
}
