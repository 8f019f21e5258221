package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** A database password on the command line still works but warns that ps shows it; from a file it is silent. */
class DatabasePasswordSourcesTest {
    @Test
    void commandLinePasswordsWarnFilePasswordsDoNot(@TempDir Path dir) throws Exception {
        Path pw = dir.resolve("pw");
        Files.writeString(pw, "from-file\n");
        DatabaseServerCommand cmd = new DatabaseServerCommand();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        cmd.err = new PrintStream(err, true, StandardCharsets.UTF_8);
        new CommandLine(cmd).parseArgs("--server", "h", "--url", "jdbc:derby://a:1527/one", "--db-user", "RIPV",
                "--db-password-file", pw.toString(), "--reader-user", "READER", "--reader-password", "on-the-line");
        DatabaseTarget t = cmd.build("h").targets().get(0);
        assertThat(t.password()).isEqualTo("from-file");
        assertThat(t.readerPassword()).isEqualTo("on-the-line");
        String warned = err.toString(StandardCharsets.UTF_8);
        assertThat(warned).contains("Warning: --reader-password").contains("ps").doesNotContain("--db-password ")
                .doesNotContain("on-the-line");
    }
}
