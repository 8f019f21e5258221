package org.ripv.text;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.LoggerContext;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** Issue 23, item 8: ESC, BEL and C1 controls are kept as data and printed escaped. */
class PrintableTest {
    static final String HOSTILE = "title\u001b]0;pwned\u0007 clear\u001b[2J csi\u009b31m bell\u0007 cr\rdel\u007f rlo\u202e";

    @Test
    void controlsAreShownAndPrintableTextIsKept() {
        String s = Printable.escape(HOSTILE + "\nnext\tline");
        assertThat(s).doesNotContainPattern("[\\x00-\\x08\\x0b-\\x1f\\x7f-\\x9f\\u202e]")
                .contains("^[]0;pwned^G").contains("^[[2J").contains("\\u009b31m").contains("\\r").contains("\\u202e")
                .contains("\nnext\tline");
        assertThat(Printable.oneLine("a\nb")).isEqualTo("a\\nb");
        String plain = "Glider ru29 at surface. ümlaut";
        assertThat(Printable.escape(plain)).isSameAs(plain);
    }

    @Test
    void theShippedLogConfigurationEscapesEveryMessage() throws Exception {
        LoggerContext ctx = new LoggerContext();
        ch.qos.logback.classic.spi.LoggingEvent event = new ch.qos.logback.classic.spi.LoggingEvent(
                "fqcn", ctx.getLogger("org.ripv.test"), ch.qos.logback.classic.Level.WARN, "vehicle said {}", null,
                new Object[] {HOSTILE});
        assertThat(new SafeMessageConverter().convert(event)).startsWith("vehicle said title^[]0;pwned^G")
                .doesNotContainPattern("[\\x00-\\x08\\x0b-\\x1f\\x7f-\\x9f]");
        // The product's configuration (not logback-test.xml) prints every message through it.
        String shipped;
        try (var in = PrintableTest.class.getResourceAsStream("/logback.xml")) {
            shipped = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        assertThat(shipped).contains("converterClass=\"org.ripv.text.SafeMessageConverter\"").contains("%safemsg")
                .doesNotContain("%msg").doesNotContain("%m%");
    }
}
