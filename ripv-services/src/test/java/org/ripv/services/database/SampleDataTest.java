package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The committed {@code sql/sample-data.sql} is exactly what {@link SampleDataGenerator} writes. */
class SampleDataTest {
    @Test
    void committedSampleDataMatchesTheGenerator() throws Exception {
        String committed = Files.readString(Path.of("..", "sql", "sample-data.sql"), StandardCharsets.UTF_8);
        assertThat(SampleDataGenerator.generate())
                .as("sql/sample-data.sql is stale: regenerate it with SampleDataGenerator (see its Javadoc)")
                .isEqualTo(committed);
        // and the jar carries the same file
        assertThat(SqlScript.resource("sample-data.sql")).isEqualTo(committed);
    }
}
