package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.it.web.WebVisitor;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.ServerConfig;
import org.ripv.server.permit.PermitFile;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;

/**
 * Issue 33 item 4: a log-in kept its roles for as long as it lasted (a web session 12 h), through a
 * demotion or a password change, so an operator moved to observers still got the DatabaseServer's
 * read-write connection. Now a permit-file reload gives every open connection and web session
 * the user's new roles at once, and a changed password or a removed user ends them.
 */
class StaleRolesAttackTest {
    static final Duration T = Duration.ofSeconds(20);
    static final String DB = "<DatabaseServer>::<localhost>TTY1";

    @TempDir
    static Path dir;
    static TestSystem sys;
    static WebVisitor web;

    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config).user("dora", "operators").user("pete", "operators").user("bob", "operators");
        sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                QueryLimits.defaults()));
        web = new WebVisitor(sys.server().httpPort(), true);
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    static OutgoingServerMessage call(ClientSocketHandler c, String mailbox, String body) throws Exception {
        return c.call(mailbox, body, Priority.NORMAL, T, p -> { });
    }

    /** The user's line in the permit file with other roles, the password (its hash) untouched, as an admin's editor does. */
    static void roles(String user, String roles) throws Exception {
        Path permit = sys.dataDir().resolve("permit.txt");
        List<String> lines = Files.readAllLines(permit, StandardCharsets.UTF_8).stream()
                .map(l -> l.startsWith("user " + user + " ") ? l.substring(0, l.lastIndexOf(' ')) + " " + roles : l).toList();
        Files.write(permit, lines, StandardCharsets.UTF_8);
        sys.server().reloadPermits();
    }

    @Test
    void aDemotedOperatorsOpenLogInsWriteNoMore() throws Exception {
        ClientSocketHandler dora = sys.login("dora");
        String cookie = web.login("dora", TestSystem.PASSWORD);
        String csrf = web.csrf(cookie);
        WebVisitor.Socket page = web.socket(cookie, web.base);
        assertThat(call(dora, DB, "CREATE TABLE before_demotion (x INT)").status()).isEqualTo(Status.OK);

        roles("dora", "observers");

        OutgoingServerMessage w = call(dora, DB, "CREATE TABLE after_demotion (x INT)");
        assertThat(w.status()).as("the open connection writes as an observer: %s", w.footer().replyText()).isEqualTo(Status.ERROR);
        page.send(7, DB, "CREATE TABLE from_the_page (x INT)", csrf);
        assertThat(page.await("\"id\":7", T)).as("the open page writes as an observer").contains("\"ERROR\"");
        assertThat(call(dora, "", "?whoami").footer().replyText()).contains("[observers]");
        assertThat(web.get("/api/session", "Cookie", cookie).body()).contains("\"roles\":[\"observers\"]");
        // Nothing was created: an operator looks.
        ClientSocketHandler bob = sys.login("bob");
        assertThat(call(bob, DB, "SELECT * FROM after_demotion").footer().replyText()).containsIgnoringCase("does not exist");
        assertThat(call(bob, DB, "SELECT * FROM from_the_page").footer().replyText()).containsIgnoringCase("does not exist");
        bob.close();
        dora.close();
    }

    @Test
    void aChangedPasswordEndsEveryOpenLogIn() throws Exception {
        ClientSocketHandler pete = sys.login("pete");
        String cookie = web.login("pete", TestSystem.PASSWORD);
        WebVisitor.Socket page = web.socket(cookie, web.base);

        PermitFile.setUser(sys.dataDir().resolve("permit.txt"), "pete", "a new password".toCharArray(), null, 1000);
        sys.server().reloadPermits();

        assertThat(page.await("CLOSED", T)).as("the open page is closed").startsWith("CLOSED");
        assertThat(web.get("/api/session", "Cookie", cookie).statusCode()).as("the web session ended").isEqualTo(401);
        long end = System.nanoTime() + T.toNanos();
        while (pete.isOpen() && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        assertThat(pete.isOpen()).as("the client connection is closed").isFalse();
    }
}
