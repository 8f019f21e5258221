package org.ripv.server.commands;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Priority;

/** The command table names each command once; ?help (and so the clients' completion) is written from it. */
class CommandTableTest {
    static final ServerCommand PING = ServerCommand.open("?ping", "000002", "?ping", "answers pong", c -> c.ok("pong", null));

    @Test
    void aWordIsNamedOnceAndFoundInAnyCase() {
        CommandTable t = new CommandTable().add(PING);
        assertThat(t.find("?PING")).contains(PING);
        assertThat(t.find("?pong")).isEmpty();
        assertThatThrownBy(() -> t.add(PING)).hasMessageContaining("?ping is named twice");
        assertThatThrownBy(() -> t.add(ServerCommand.open("?Ping", "000002", "?Ping", "", c -> null)))
                .hasMessageContaining("lower-case");
    }

    @Test
    void helpListsEveryCommandInOrderWithItsUsageAndFid() {
        CommandTable t = new CommandTable().add(PING).add(ServerCommand.open("?lock", "000015", "?lock MAILBOX [SECONDS]",
                "keep others from commanding a MailBox", c -> null).needsRight());
        String[] lines = t.help().split("\\R");
        assertThat(lines[0]).isEqualTo("Server commands:");
        assertThat(lines[1]).isEqualTo(String.format("  %-32s %s  [FID %s]", "?ping", "answers pong", "000002"));
        assertThat(lines[2]).startsWith("  ?lock MAILBOX [SECONDS]").endsWith("[FID 000015]");
        assertThat(lines[3]).isEqualTo("Anything else goes to the chosen MailBox of a service.");
        assertThat(t.all()).extracting(ServerCommand::word).containsExactly("?ping", "?lock");
        assertThat(t.find("?lock").orElseThrow().gated()).isTrue();
        assertThat(PING.gated()).isFalse();
        assertThat(PING.onFileWork().runs()).isEqualTo(ServerCommand.Runs.FILE_WORK);
    }

    @Test
    void aCallQuotesTheUsageWhenWordsAreMissing() {
        IncomingServerMessage r = new IncomingServerMessage(Header.request(1, "", "?lock", Priority.NORMAL)
                .withOrigin(new IdBadge("123456", "alice"), List.of()));
        ServerCommand lock = ServerCommand.open("?lock", "000015", "?lock MAILBOX [SECONDS]", "", c -> null);
        Call call = new Call(r, lock, new String[] {"?lock"}, null);
        assertThatThrownBy(() -> call.arg(1)).hasMessage("usage: ?lock MAILBOX [SECONDS]");
        assertThatThrownBy(() -> Call.number("ten", "SECONDS")).hasMessage("SECONDS must be a whole number, got 'ten'");
        assertThat(call.error(org.ripv.messages.ErrorCode.BAD_REQUEST, "no").footer().route()).contains("RIPVServer");
    }
}
