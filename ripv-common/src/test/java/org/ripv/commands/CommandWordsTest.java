package org.ripv.commands;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

class CommandWordsTest {
    static final class Add {
        @Parameters(index = "0", paramLabel = "MAILBOX")
        String mailbox;
        @Parameters(index = "1", paramLabel = "NAME")
        String name;
        @Option(names = "--typed")
        boolean typed;
    }

    @Test
    void theUsageIsWrittenFromTheDeclaration() {
        assertThat(CommandWords.usage("?queue add", new Add())).isEqualTo("?queue add MAILBOX NAME [--typed]");
        assertThat(CommandWords.optionNames(new Add())).containsExactly("--typed");
    }

    @Test
    void wordsFillTheObjectAndOptionsTakeAnyCase() {
        Add a = CommandWords.parse(new Add(), "u", "gliders:rosie", "plan.wf", "--TYPED");
        assertThat(a.mailbox).isEqualTo("gliders:rosie");
        assertThat(a.name).isEqualTo("plan.wf");
        assertThat(a.typed).isTrue();
        assertThat(CommandWords.parse(new Add(), "u", "m", "n").typed).isFalse();
    }

    @Test
    void aHostileLineIsRefusedWithTheReasonAndTheUsage() {
        assertThatThrownBy(() -> CommandWords.parse(new Add(), "?queue add MAILBOX NAME [--typed]", "m", "n", "--typo"))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("--typo")
                .hasMessageEndingWith("; usage: ?queue add MAILBOX NAME [--typed]");
        assertThatThrownBy(() -> CommandWords.parse(new Add(), "u", "m")).hasMessageContaining("NAME");
        // no abbreviations, and @file is a word, never a file the server reads
        assertThatThrownBy(() -> CommandWords.parse(new Add(), "u", "m", "n", "--ty")).isInstanceOf(IllegalArgumentException.class);
        Add at = CommandWords.parse(new Add(), "u", "@/etc/passwd", "n");
        assertThat(at.mailbox).isEqualTo("@/etc/passwd");
    }
}
