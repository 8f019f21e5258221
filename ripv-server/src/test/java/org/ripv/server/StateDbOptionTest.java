package org.ripv.server;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.server.store.StoreLocation;
import picocli.CommandLine;

/** {@code ripv server --state-db URL --state-db-user U --state-db-password-file F}, as the command line reads them. */
class StateDbOptionTest {
    @TempDir
    Path dir;

    private static StoreLocation parse(String... args) throws Exception {
        ServerMain.Serve serve = new ServerMain.Serve();
        new CommandLine(serve).parseArgs(args);
        return serve.stateStore.location(new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
    }

    @Test
    void theDefaultIsEmbedded() throws Exception {
        assertThat(parse().isEmbedded()).isTrue();
        assertThat(ServerConfig.defaults(dir).stateStore().isEmbedded()).isTrue();
    }

    @Test
    void aUrlUserAndPasswordFileMakeAPostgresStore() throws Exception {
        Path pw = dir.resolve("pw");
        Files.writeString(pw, "s3cret\n");
        StoreLocation l = parse("--state-db", "jdbc:postgresql://db.example:5432/ripv", "--state-db-user", "ripv",
                "--state-db-password-file", pw.toString());
        assertThat(l.jdbcUrl()).isEqualTo("jdbc:postgresql://db.example:5432/ripv");
        assertThat(l.user()).isEqualTo("ripv");
        assertThat(l.password()).isEqualTo("s3cret");
        assertThat(l.toString()).doesNotContain("s3cret").contains("db.example");
    }

    @Test
    void mistakesAreClearErrors() {
        assertThatThrownBy(() -> parse("--state-db-user", "ripv")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("need --state-db");
        assertThatThrownBy(() -> parse("--state-db", "jdbc:mysql://h/db")).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("--state-db takes a PostgreSQL JDBC URL");
        assertThatThrownBy(() -> parse("--state-db", "jdbc:postgresql://h/db", "--state-db-password-file", dir.resolve("none").toString()))
                .isInstanceOf(java.io.IOException.class).hasMessageContaining("cannot read --state-db-password-file");
    }

    @Test
    void aDatabaseThatCannotBeReachedStopsTheServerWithTheReason() throws Exception {
        StringWriter err = new StringWriter();
        CommandLine cl = org.ripv.launch.Launchers.commandLine(new ServerMain(), "ripv");
        cl.setErr(new PrintWriter(err));
        int code = cl.execute("server", "--data", dir.resolve("data").toString(), "--port", "0", "--registry-port", "0",
                "--http-port", "0", "--outbound-port", "-1", "--plain", "--state-db", "jdbc:postgresql://127.0.0.1:1/ripv?password=hunter2");
        assertThat(code).isEqualTo(1);
        assertThat(err.toString()).contains("cannot use the state database jdbc:postgresql://127.0.0.1:1/ripv?password=***")
                .doesNotContain("hunter2");
    }
}
