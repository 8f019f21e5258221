package org.ripv.commands;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class SingleLineCommandTest {
    @Test
    void plainLinesAndTabsPass() {
        assertThat(SingleLineCommand.check("dir", 1024)).isEqualTo("dir");
        assertThat(SingleLineCommand.check("type\tMISSION1.LOG  ", 1024)).isEqualTo("type\tMISSION1.LOG  ");
        assertThat(SingleLineCommand.check("SELECT 'é' FROM x", 1024)).isNotEmpty();
    }

    @Test
    void everyControlCharacterButTabIsRefused() {
        for (char c : new char[] {'\r', '\n', 0, 3, 0x1b, 0x7f, 0x80, 0x85, 0x9b, 0x9f, '\u2028', '\u2029'}) {
            assertThatThrownBy(() -> SingleLineCommand.check("dir" + c + "GO", 1024))
                    .as("code %d", (int) c).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("control character").hasMessageContaining("position 4");
        }
        assertThatThrownBy(() -> SingleLineCommand.check("dir\r\ndel GLIDER.CFG", 1024))
                .hasMessageContaining("CR").hasMessageContaining("dir\\r\\ndel GLIDER.CFG");
    }

    @Test
    void longCommandsAreRefusedAndQuotedShort() {
        String longOne = "dir" + "x".repeat(1_000_000);
        assertThatThrownBy(() -> SingleLineCommand.check(longOne, 1024))
                .hasMessageContaining("1000003 characters").hasMessageContaining("at most 1024")
                .satisfies(e -> assertThat(e.getMessage().length()).isLessThan(300));
        assertThat(SingleLineCommand.check("x".repeat(1024), 1024)).hasSize(1024);
    }

    @Test
    void shownMakesControlsVisibleAndCuts() {
        assertThat(SingleLineCommand.shown("a\u0003b\u001b")).isEqualTo("a^Cb^[");
        assertThat(SingleLineCommand.shown("y".repeat(500))).hasSize(80).endsWith("...");
    }
}
