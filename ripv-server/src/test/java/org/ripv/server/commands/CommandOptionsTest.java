package org.ripv.server.commands;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.commands.OptionValues;
import org.ripv.server.session.ConsoleCommands;
import org.ripv.server.store.AuditCommand;
import org.ripv.server.surfacing.SurfacingCommands;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** A command's options are named once, in its picocli class: the usage ?help shows and the parsing both come from it. */
class CommandOptionsTest {
    static final class Words {
        @Parameters(index = "0", paramLabel = "MAILBOX")
        String mailbox;
        @Option(names = "--last", paramLabel = "N")
        int last = 5;
        @Option(names = "--json")
        boolean json;
    }

    static final ServerCommand WORDS = ServerCommand.parsed("?words", "000099", Words::new, "a test", c -> null);

    @Test
    void theUsageIsWrittenFromTheOptions() {
        assertThat(WORDS.usage()).isEqualTo("?words MAILBOX [--last N] [--json]");
        assertThat(WORDS.optionNames()).containsExactly("--last", "--json");
        assertThat(ServerCommand.parsed("?history", "1", ConsoleCommands.History::new, "", c -> null).usage())
                .isEqualTo("?history MAILBOX [--last N] [--since ISO-TIME]");
        assertThat(ServerCommand.parsed("?audit", "1", AuditCommand.Options::new, "", c -> null).usage())
                .isEqualTo("?audit [--last N] [--since ISO-TIME]");
        assertThat(ServerCommand.parsed("?surfacings", "1", SurfacingCommands.Options::new, "", c -> null).usage())
                .isEqualTo("?surfacings MAILBOX [--last N] [--json] [--outlook]");
        assertThat(ServerCommand.parsed("?dac", "1", ServerCommands.Dac::new, "", c -> null).usage())
                .isEqualTo("?dac MAILBOX [GLIDER] [--json]");
        assertThat(ServerCommand.open("?ping", "1", "?ping", "", c -> null).optionNames()).isEmpty();
    }

    @Test
    void aLineIsParsedIntoAFreshObjectInAnyCase() {
        Words w = (Words) WORDS.parse("?words ru29 --LAST 7 --Json".split(" "));
        assertThat(w.mailbox).isEqualTo("ru29");
        assertThat(w.last).isEqualTo(7);
        assertThat(w.json).isTrue();
        Words again = (Words) WORDS.parse("?words ru30".split(" "));
        assertThat(again.last).isEqualTo(5);
        assertThat(again.json).isFalse();
    }

    @Test
    void aBadLineGetsPicocliSWordsAndTheUsage() {
        assertThatThrownBy(() -> WORDS.parse("?words ru29 --colour red".split(" ")))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("--colour")
                .hasMessageEndingWith("usage: ?words MAILBOX [--last N] [--json]");
        assertThatThrownBy(() -> WORDS.parse("?words ru29 --last".split(" "))).hasMessageContaining("--last");
        assertThatThrownBy(() -> WORDS.parse("?words ru29 --last ten".split(" "))).hasMessageContaining("'ten'");
        assertThatThrownBy(() -> WORDS.parse("?words".split(" "))).hasMessageContaining("MAILBOX");
        assertThatThrownBy(() -> WORDS.parse("?words ru29 ru30".split(" "))).hasMessageContaining("ru30");
        assertThatThrownBy(() -> WORDS.parse("?words ru29 --la 3".split(" "))).hasMessageContaining("--la");
    }

    @Test
    void theSharedValuesKeepTheirWords() {
        ServerCommand audit = ServerCommand.parsed("?audit", "1", AuditCommand.Options::new, "", c -> null);
        assertThatThrownBy(() -> audit.parse("?audit --last 0".split(" "))).hasMessageContaining("--last takes a whole number from 1 to 1000");
        assertThatThrownBy(() -> audit.parse("?audit --since yesterday".split(" "))).hasMessageContaining("--since takes");
        assertThat(audit.parse("?audit --since 2026-11-23 --last 1000".split(" "))).isNotNull();
        assertThat(new OptionValues.IsoTime().convert("2026-11-23T14:00")).isEqualTo(Instant.parse("2026-11-23T14:00:00Z"));
    }

    /** A client's line is hostile: an @FILE word is a word, never the server's file read as arguments. */
    @Test
    void anAtFileIsNotRead(@TempDir Path dir) throws Exception {
        Path args = Files.writeString(dir.resolve("args"), "--last 9");
        Words w = (Words) WORDS.parse(new String[] {"?words", "@" + args});
        assertThat(w.mailbox).isEqualTo("@" + args);
        assertThat(w.last).isEqualTo(5);
    }
}
