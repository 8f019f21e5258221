package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** The launcher's options and the thesis's positional form. */
class DatabaseServerCommandTest {
    @Test
    void thesisFormBecomesOptions() {
        assertThat(DatabaseServerCommand.thesisArgs(new String[] {"//deslab.mit.edu"}))
                .containsExactly("--server", "//deslab.mit.edu");
        assertThat(DatabaseServerCommand.thesisArgs(new String[] {"//deslab", "org.postgresql.Driver", "jdbc:postgresql://db/ripv"}))
                .containsExactly("--server", "//deslab", "--driver", "org.postgresql.Driver", "--url", "jdbc:postgresql://db/ripv");
        assertThat(DatabaseServerCommand.thesisArgs(new String[] {"//deslab", "jdbc:derby://db:1527/v", "--max-rows", "5"}))
                .containsExactly("--server", "//deslab", "--url", "jdbc:derby://db:1527/v", "--max-rows", "5");
        assertThat(DatabaseServerCommand.thesisArgs(new String[] {"--server", "x"})).containsExactly("--server", "x");
    }

    @Test
    void severalUrlsGiveSeveralMailBoxesWithTheirOwnSettings(@TempDir Path dir) throws Exception {
        Path pw = dir.resolve("pw");
        Files.writeString(pw, "s3cret\n");
        DatabaseServerCommand cmd = new DatabaseServerCommand();
        new CommandLine(cmd).parseArgs(DatabaseServerCommand.thesisArgs(new String[] {
                "//ripv.example.org", "org.apache.derby.jdbc.ClientDriver", "jdbc:derby://a:1527/one",
                "--db-user", "RIPV", "--db-password-file", pw.toString(), "--reader-user", "READER", "--reader-password", "r",
                "--url", "jdbc:postgresql://b/two", "--db-user", "pg", "--max-rows", "77", "--query-timeout", "3"}));
        DatabaseServer s = cmd.build("h");
        assertThat(s.targets()).hasSize(2);
        DatabaseTarget one = s.targets().get(0);
        assertThat(one.handle()).isEqualTo("TTY1");
        assertThat(one.driver()).isEqualTo("org.apache.derby.jdbc.ClientDriver");
        assertThat(one.password()).isEqualTo("s3cret");
        assertThat(one.hasReader()).isTrue();
        DatabaseTarget two = s.targets().get(1);
        assertThat(two.handle()).isEqualTo("TTY2");
        assertThat(two.url()).isEqualTo("jdbc:postgresql://b/two");
        assertThat(two.user()).isEqualTo("pg");
        assertThat(two.hasReader()).isFalse();
        assertThat(s.limits().maxRows()).isEqualTo(77);
        assertThat(s.limits().queryTimeoutSeconds()).isEqualTo(3);
    }

    @Test
    void noUrlMeansTheEmbeddedDefaultInTheDataDirectory(@TempDir Path dir) throws Exception {
        DatabaseServerCommand cmd = new DatabaseServerCommand();
        new CommandLine(cmd).parseArgs("--server", "localhost", "--data", dir.toString());
        DatabaseServer s = cmd.build("h");
        assertThat(s.targets()).singleElement().satisfies(t -> {
            assertThat(t.handle()).isEqualTo("TTY1");
            assertThat(t.embeddedDerby()).isTrue();
            assertThat(t.hasReader()).isTrue();
        });
        assertThat(dir.resolve("vehicledb")).isDirectory();
        EmbeddedDatabase.shutdown(s.targets().get(0).url(), s.targets().get(0).password());
    }

    @Test
    void badUsageExitsWithTwo() {
        assertThat(DatabaseServerCommand.run("--max-rows", "x")).isEqualTo(2);
        assertThat(DatabaseServerCommand.run("--server", "h", "--db-user", "u")).isEqualTo(2); // --db-user without --url
    }
}
