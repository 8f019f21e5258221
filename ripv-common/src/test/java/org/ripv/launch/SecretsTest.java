package org.ripv.launch;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class SecretsTest {
    @TempDir
    Path dir;
    final ByteArrayOutputStream err = new ByteArrayOutputStream();
    final PrintStream errStream = new PrintStream(err, true, StandardCharsets.UTF_8);

    @Test
    void onTheCommandLineItWorksButWarns() throws Exception {
        assertThat(Secrets.resolve("hunter2", null, "RIPV_NO_SUCH_VAR", "--db-password", false, errStream)).isEqualTo("hunter2");
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("Warning: --db-password").contains("ps")
                .contains("--db-password-file").doesNotContain("hunter2");
    }

    @Test
    void aFileGivesItsFirstLineSilently() throws Exception {
        Path f = dir.resolve("pw");
        Files.writeString(f, "s3cret  \nignored\n");
        assertThat(Secrets.resolve(null, f, null, "--db-password", false, errStream)).isEqualTo("s3cret");
        assertThat(err.size()).isZero();
        assertThatThrownBy(() -> Secrets.resolve("x", f, null, "--db-password", false, errStream))
                .hasMessageContaining("not both");
    }

    @Test
    void theEnvironmentIsTriedWhenNothingElseIsGiven() throws Exception {
        // PATH is always set: it stands in for RIPV_DB_PASSWORD here
        assertThat(Secrets.resolve(null, null, "PATH", "--db-password", false, errStream)).isEqualTo(System.getenv("PATH"));
        assertThat(Secrets.resolve(null, null, "RIPV_NO_SUCH_VAR_42", "--db-password", true, errStream)).isNull();
    }
}
