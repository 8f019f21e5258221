package org.ripv.server.permit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PermitFileTest {
    @TempDir
    Path dir;

    @Test
    void aMissingFileIsCreatedFromTheTemplateWithNoUsers() throws Exception {
        Path f = dir.resolve("permit.txt");
        PermitFile p = PermitFile.load(f);
        assertThat(Files.readString(f)).isEqualTo(PermitFile.TEMPLATE);
        assertThat(p.users()).isEmpty();
    }

    @Test
    void passwdAddsAndChangesUsersAndKeepsRoles() throws Exception {
        Path f = dir.resolve("permit.txt");
        PermitFile.setUser(f, "alice", "first password".toCharArray(), List.of("operators"), 1000);
        PermitFile.setUser(f, "bob", "bob's password".toCharArray(), List.of("observers", "db-reader"), 1000);
        PermitFile.setUser(f, "alice", "second password".toCharArray(), null, 1000);
        PermitFile p = PermitFile.load(f);
        assertThat(p.authenticate("alice", "second password".toCharArray())).isPresent();
        assertThat(p.authenticate("alice", "first password".toCharArray())).isEmpty();
        assertThat(p.user("alice").orElseThrow().roles()).containsExactly("operators");
        assertThat(p.user("bob").orElseThrow().roles()).containsExactly("observers", "db-reader");
        assertThat(p.authenticate("carol", "anything".toCharArray())).isEmpty();
        assertThat(Files.readString(f)).doesNotContain("second password").contains("pbkdf2-sha256$1000$");
        assertThatThrownBy(() -> PermitFile.setUser(f, "bad name", "x".toCharArray(), null, 1000))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("bad name");
    }

    @Test
    void theTemplateLetsObserversSendNothingToAVehicle() throws Exception {
        Path f = dir.resolve("permit.txt");
        PermitFile.setUser(f, "olga", "observer password".toCharArray(), List.of("observers"), 1000);
        PermitFile.setUser(f, "otto", "operator password".toCharArray(), List.of("operators"), 1000);
        PermitFile p = PermitFile.load(f);
        PermitFile.User olga = p.user("olga").orElseThrow();
        PermitFile.User otto = p.user("otto").orElseThrow();
        // Issue 23, item 12: observers watch; a few precious minutes of an Iridium call are not theirs.
        assertThat(p.decide(olga, "SerialPortServer", "ttyS0", "dir").allowed()).isFalse();
        assertThat(p.decide(olga, "SerialPortServer", "ttyS0", "type mission1.log").allowed()).isFalse();
        assertThat(p.decide(olga, "SerialPortServer", "ttyS0", "ymodem:get mission1.log").allowed()).isFalse();
        assertThat(p.decide(olga, "SerialPortServer", "ttyS0", "?read").allowed()).isTrue();
        assertThat(p.decide(olga, "RIPVServer", "", "?download ttyS0/MISSION1.LOG").allowed()).isTrue();
        assertThat(p.decide(olga, "SerialPortServer", "ttyS0", "ymodem:put new.bin").allowed()).isFalse();
        assertThat(p.decide(olga, "SerialPortServer", "ttyS0", "GO").allowed()).isFalse();
        assertThat(p.decide(olga, "SerialPortServer", "ttyS0", "go").allowed()).isFalse();
        assertThat(p.decide(olga, "DatabaseServer", "TTY1", "SELECT * FROM mission").allowed()).isTrue();
        assertThat(p.decide(otto, "SerialPortServer", "ttyS0", "GO").allowed()).isTrue();
        assertThat(p.decide(otto, "SerialPortServer", "ttyS0", "ymodem:put new.bin").allowed()).isTrue();
    }

    @Test
    void firstMatchingRuleWinsAndNoMatchMeansNo() {
        PermitFile p = PermitFile.parse(dir.resolve("p"), List.of(
                "user u pbkdf2-sha256$1000$AAAA$AAAA team",
                "deny u Svc ttyS1 *",
                "allow @team Svc tty* dir*",
                "allow * Other * exact command"));
        PermitFile.User u = p.user("u").orElseThrow();
        assertThat(p.decide(u, "Svc", "ttyS0", "dir /w").allowed()).isTrue();
        assertThat(p.decide(u, "Svc", "ttyS1", "dir").allowed()).isFalse();
        assertThat(p.decide(u, "Svc", "ttyS0", "del x").because()).contains("no rule");
        assertThat(p.decide(u, "Other", "x", "exact command").allowed()).isTrue();
        assertThat(p.decide(u, "Other", "x", "exact command plus").allowed()).isFalse();
    }

    @Test
    void malformedLinesNameTheLine() {
        assertThatThrownBy(() -> PermitFile.parse(dir.resolve("p"), List.of("# ok", "alow * * * *")))
                .hasMessageContaining(":2:").hasMessageContaining("alow");
        assertThatThrownBy(() -> PermitFile.parse(dir.resolve("p"), List.of("allow * *")))
                .hasMessageContaining("allow WHO SERVICE MAILBOX COMMAND-PATTERN");
    }

    @Test
    void malformedHashesNeverMatch() {
        assertThat(Passwords.verify("x".toCharArray(), "plaintext")).isFalse();
        assertThat(Passwords.verify("x".toCharArray(), "pbkdf2-sha256$10$AAAA$AAAA")).isFalse();
        assertThat(Passwords.verify("x".toCharArray(), "pbkdf2-sha256$notanumber$AAAA$AAAA")).isFalse();
        String h = Passwords.hash("right".toCharArray(), 1000);
        assertThat(Passwords.verify("right".toCharArray(), h)).isTrue();
        assertThat(Passwords.verify("wrong".toCharArray(), h)).isFalse();
        assertThat(Passwords.hash("right".toCharArray(), 1000)).isNotEqualTo(h);
    }
}
