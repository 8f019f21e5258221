package org.ripv.server.permit;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Whether a page shows a user a command line (issue 32 item 7): decided by the rules, read in order
 * as {@code decide} reads them, whatever the roles are called.
 */
class MaySendSomethingTest {
    static final String HASH = "pbkdf2-sha256$1000$AAAA$AAAA";

    static PermitFile file(String... rules) {
        List<String> lines = new ArrayList<>(List.of("user alice " + HASH + " operators", "user olga " + HASH + " observers",
                "user vic " + HASH + " visitors", "user pia " + HASH + " pilots", "user obi " + HASH + " observers"));
        lines.addAll(List.of(rules));
        lines.addAll(List.of(PermitFile.TEMPLATE.split("\n")));
        return PermitFile.parse(Path.of("p"), lines);
    }

    static boolean may(PermitFile p, String user, String service) {
        return p.maySendSomething(p.user(user).orElseThrow(), service, "glider1");
    }

    @Test
    void theRulesDecideNotTheRolesName() {
        PermitFile p = file("allow @visitors * * ?read", "deny @visitors * * *",
                "allow @pilots * * ?read", "allow @pilots SerialPortServer * ?key ctrl-c", "deny @pilots * * *",
                "allow obi SerialPortServer glider1 dir*");
        assertThat(may(p, "alice", "SerialPortServer")).as("operators: allow * * *").isTrue();
        assertThat(may(p, "olga", "SerialPortServer")).as("the template's observers: ?read, then deny").isFalse();
        assertThat(may(p, "olga", "DatabaseServer")).as("observers query the database").isTrue();
        assertThat(may(p, "vic", "SerialPortServer")).as("only ?read").isFalse();
        assertThat(may(p, "pia", "SerialPortServer")).as("a key is no command line").isFalse();
        assertThat(may(p, "obi", "SerialPortServer")).as("an observer allowed dir before the deny").isTrue();
        assertThat(p.maySendSomething(p.user("obi").orElseThrow(), "SerialPortServer", "glider2")).as("on glider1 only").isFalse();
    }

    @Test
    void noRuleNoRight() {
        PermitFile p = PermitFile.parse(Path.of("p"), List.of("user vic " + HASH + " visitors"));
        assertThat(may(p, "vic", "SerialPortServer")).isFalse();
    }
}
