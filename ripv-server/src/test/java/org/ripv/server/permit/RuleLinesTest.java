package org.ripv.server.permit;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A rule speaks about one whole line: a glob never runs across a line break or a control character. */
class RuleLinesTest {
    final PermitFile p = PermitFile.parse(Path.of("p"), List.of(
            "user u pbkdf2-sha256$1000$AAAA$AAAA team",
            "allow @team SerialPortServer * dir*",
            "allow * * * *"));
    final PermitFile.User u = p.user("u").orElseThrow();

    @Test
    void aGlobDoesNotSwallowASecondLine() {
        assertThat(p.decide(u, "SerialPortServer", "ttyV0", "dir /w").allowed()).isTrue();
        for (String evil : List.of("dir\rGO", "dir\r\ndel GLIDER.CFG", "dir\nGO", "dir\u0003", "dir\u001b", "dir\u0085GO",
                "dir\u2028GO", "dir\u0000")) {
            assertThat(p.decide(u, "SerialPortServer", "ttyV0", evil).allowed()).as(evil).isFalse();
        }
    }

    @Test
    void starMatchesNoControlCharacterEither() {
        assertThat(Rule.glob("*").matcher("a\nb").matches()).isFalse();
        assertThat(Rule.glob("dir*").matcher("dir\rGO").matches()).isFalse();
    }
}
