package org.ripv.client.cli.shell;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

class CompletionsTest {
    static final String VIS = "<DataVisServer>::<shore>TTY1";
    static final String GLIDER = "<SerialPortServer>::<shore>ru29";

    final Facts facts = new Facts() {
        @Override
        public List<String> serverCommands() {
            return List.of("?help", "?mailboxes", "?services");
        }

        @Override
        public List<String> mailboxes() {
            return List.of(GLIDER, VIS);
        }

        @Override
        public List<String> downloads() {
            return List.of("01230000.dbd");
        }

        @Override
        public List<String> uploads() {
            return List.of("temp.dat");
        }

        @Override
        public List<String> serviceCommands(String mailbox) {
            return mailbox.equals(VIS) ? List.of("vis:") : List.of("dir", "type");
        }

        @Override
        public List<String> attachPrefixes(String mailbox) {
            return mailbox.equals(VIS) ? List.of("vis:") : List.of();
        }
    };
    final Completions c = new Completions(facts);

    @Test
    void firstWordsAreTheClisTheServersAndTheServicesCommands() {
        assertThat(c.candidates(List.of("?mai"), 0, "")).contains("?mailboxes", "use", "get").doesNotContain("dir");
        assertThat(c.candidates(List.of("d"), 0, GLIDER)).contains("dir", "type", "?help");
    }

    @Test
    void theClisOwnWordsAreAGroupOfTheirOwnAndSendTakesTheMailBoxsCommands() {
        assertThat(c.candidates(List.of("s"), 0, GLIDER)).contains("send", "?services");
        assertThat(Completions.group("send")).isEqualTo(Completions.OWN_GROUP).contains("the CLI's own words");
        assertThat(Completions.group("put")).isEqualTo(Completions.OWN_GROUP);
        assertThat(Completions.group("exit")).isEqualTo(Completions.OWN_GROUP);
        assertThat(Completions.group("?help")).isEqualTo(Completions.SERVER_GROUP);
        assertThat(Completions.group("dir")).isEqualTo(Completions.MAILBOX_GROUP);
        assertThat(c.candidates(List.of("send", ""), 1, GLIDER)).containsExactly("dir", "type");
    }

    @Test
    void mailboxesAfterUseFilesAfterGetPrioritiesAfterPriority() {
        assertThat(c.candidates(List.of("use", ""), 1, "")).containsExactly(GLIDER, VIS);
        assertThat(c.candidates(List.of("?lock", "<S"), 1, "")).containsExactly(GLIDER, VIS);
        assertThat(c.candidates(List.of("get", ""), 1, "")).containsExactly("01230000.dbd");
        assertThat(c.candidates(List.of("?delete", ""), 1, "")).containsExactly("temp.dat", "01230000.dbd");
        assertThat(c.candidates(List.of("priority", ""), 1, "")).containsExactly("normal", "priority", "urgent");
        assertThat(c.candidates(List.of("put", "a.txt", ""), 2, "")).containsExactly("--replace", "--keep");
    }

    @Test
    void anAttachPrefixCompletesToUploads() {
        assertThat(c.candidates(List.of("vis:te"), 0, VIS)).contains("vis:temp.dat", "vis:");
        assertThat(c.candidates(List.of("vis:te"), 0, GLIDER)).doesNotContain("vis:temp.dat");
    }

    @Test
    void commandsAreReadFromAServicesHelp() {
        assertThat(Completions.commandsIn("dir, type NAME, del NAME, ys NAME..., yr, go\r\n"))
                .containsExactly("dir", "type", "del", "ys", "yr", "go");
        assertThat(Completions.commandsIn("vis:NAME [out=NAME] [title=\"...\"] plots NAME from the upload directory; worker: builtin"))
                .containsExactly("vis:");
    }

    @Test
    void thePromptShowsUserHostAndTheMailboxHandle() {
        assertThat(Shell.prompt("alice", "shore:4444", GLIDER)).isEqualTo("alice@shore ru29> ");
        assertThat(Shell.prompt("alice", "shore:4444", "")).isEqualTo("alice@shore> ");
    }

    @Test
    void aServerCommandsOptionsComeFromItsHelpLine() {
        String help = "Server commands:\n  ?history MAILBOX [--last N] [--since ISO-TIME]  its transcript  [FID 000027]\n"
                + "  ?surfacings MAILBOX [--last N] [--json]  its call records  [FID 000031]\n"
                + "Anything else goes to the chosen MailBox of a service.";
        assertThat(Completions.optionsIn(help, "?history")).containsExactly("--last", "--since");
        assertThat(Completions.optionsIn(help, "?SURFACINGS")).containsExactly("--last", "--json");
        assertThat(Completions.optionsIn(help, "?ping")).isEmpty();
        assertThat(Completions.takesMailboxIn(help, "?history")).isTrue();
        assertThat(Completions.takesMailboxIn(help, "?ping")).isFalse();
        assertThat(Completions.takesMailboxIn("  ?changes [MAILBOX]  each change  [FID 1]", "?changes")).isTrue();
        Facts withOptions = new Facts() {
            @Override
            public List<String> serverCommands() {
                return List.of("?history");
            }

            @Override
            public List<String> serverOptions(String command) {
                return Completions.optionsIn(help, command);
            }

            @Override
            public boolean serverTakesMailbox(String command) {
                return Completions.takesMailboxIn(help, command);
            }

            @Override
            public List<String> mailboxes() {
                return List.of("<SerialPortServer>::<shore>ru29");
            }

            @Override
            public List<String> downloads() {
                return List.of();
            }

            @Override
            public List<String> uploads() {
                return List.of();
            }

            @Override
            public List<String> serviceCommands(String mailbox) {
                return List.of();
            }

            @Override
            public List<String> attachPrefixes(String mailbox) {
                return List.of();
            }
        };
        assertThat(new Completions(withOptions).candidates(List.of("?history", "ru29", "--"), 2, ""))
                .containsExactly("--last", "--since");
        assertThat(new Completions(withOptions).candidates(List.of("?surfacings", ""), 1, ""))
                .containsExactly("<SerialPortServer>::<shore>ru29");
    }
}
