package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * docs/security.md says how many attacks the suite tries ("Keep them shut"); this keeps that
 * number equal to the {@code @Test} methods of the {@code …AttackTest} classes here, so a new
 * surface's attacks are counted in the document the day they are added.
 */
class AttackCountTest {
    @Test
    void theDocumentSaysHowManyAttacksTheSuiteTries() throws Exception {
        Path here = Path.of("src", "test", "java", "org", "ripv", "it", "security");
        int attacks = 0;
        int classes = 0;
        try (var files = Files.list(here)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                if (f.getFileName().toString().endsWith("AttackTest.java")) {
                    classes++;
                    Matcher m = Pattern.compile("@Test\\b").matcher(Files.readString(f, StandardCharsets.UTF_8));
                    while (m.find()) {
                        attacks++;
                    }
                }
            }
        }
        String doc = Files.readString(Path.of("..", "docs", "security.md"), StandardCharsets.UTF_8);
        Matcher said = Pattern.compile("The suite today: (\\d+) attacks in (\\d+) `…AttackTest` classes").matcher(doc);
        assertThat(said.find()).as("docs/security.md states the count").isTrue();
        assertThat(said.group(1) + " attacks in " + said.group(2) + " classes")
                .as("update 'The suite today' in docs/security.md").isEqualTo(attacks + " attacks in " + classes + " classes");
    }
}
