package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.ripv.it.ops.RunnableDocs.Block;

/**
 * No code block in README.md or docs/ rots unseen (docs/README.md, "Code blocks"): each fenced
 * block says what it holds. A shell block ({@code sh}) is either run by {@link RunnableDocsTest}
 * ({@code sh runnable}) or opens with a comment saying what it needs that one machine with the demo
 * does not have ({@code # needs real hardware: …}, {@code # needs a second host: …}); a
 * {@code synopsis} block shows a command's form with placeholders and brackets, a {@code markdown}
 * block shows a piece of a page; any other block names its language or {@code text}, and must not
 * hold a {@code ripv}, {@code mvn} or {@code java} command line (that is a shell block wearing
 * another name). An indented code block cannot say any of this, so one holding a command line fails
 * too.
 */
class DocsCodeBlocksTest {
    static final Set<String> SHELLS = Set.of("sh", "bash", "shell", "console");
    /** Blocks that may hold command lines without being run: a command's form, a page's source. */
    static final Set<String> FORMS = Set.of("synopsis", "markdown");
    static final Pattern NEEDS = Pattern.compile("#\\s*needs\\s+\\S.*");
    static final Pattern COMMAND = Pattern.compile("^(\\$\\s+)?(\\./)?(ripv|mvn|java|scripts/\\S+)\\s.*");

    /** The lines of indented (unfenced) code blocks that hold a command line. */
    static List<String> indentedCommands(Path doc) throws Exception {
        List<String> lines = Files.readAllLines(doc, StandardCharsets.UTF_8);
        List<String> out = new ArrayList<>();
        String fence = null;
        boolean inIndented = false;
        for (int i = 0; i < lines.size(); i++) {
            String l = lines.get(i);
            String t = l.strip();
            if (fence == null && (t.startsWith("```") || t.startsWith("~~~"))) {
                fence = t.substring(0, RunnableDocs.fenceLength(t));
                continue;
            }
            if (fence != null) {
                fence = t.equals(fence) ? null : fence;
                continue;
            }
            boolean indented = l.startsWith("    ") && !t.isEmpty();
            inIndented = indented && (inIndented || i > 0 && lines.get(i - 1).isBlank());
            if (inIndented && COMMAND.matcher(t).matches()) {
                out.add(doc.getFileName() + ":" + (i + 1) + " is an indented command (" + t
                        + "): put it in a fenced sh block that says whether it runs");
            }
        }
        return out;
    }

    /** Why the block is not acceptable, or null. */
    static String problem(Block b) {
        if (b.info().isEmpty()) {
            return "has no info string: say what it holds (sh runnable, sh with '# needs …', text, java, json, …)";
        }
        List<String> words = List.of(b.info().split("\\s+"));
        String lang = words.get(0);
        if (SHELLS.contains(lang)) {
            if (words.contains(RunnableDocs.MARKER)) {
                return null;
            }
            String first = b.body().stream().map(String::strip).filter(l -> !l.isEmpty()).findFirst().orElse("");
            return NEEDS.matcher(first).matches() ? null
                    : "is a shell block neither runnable ('" + lang + " runnable') nor opening with '# needs …' saying why not";
        }
        if (FORMS.contains(lang)) {
            return null;
        }
        for (String l : b.body()) {
            if (COMMAND.matcher(l.strip()).matches()) {
                return "is marked '" + b.info() + "' but holds a command line (" + l.strip() + "): make it an sh block";
            }
        }
        return null;
    }

    @Test
    void everyCodeBlockIsRunOrSaysWhyNot() throws Exception {
        List<String> bad = new ArrayList<>();
        int shells = 0;
        for (Path doc : RunnableDocs.documents(RunnableDocsTest.ROOT)) {
            for (Block b : RunnableDocs.blocks(doc)) {
                String p = problem(b);
                if (p != null) {
                    bad.add(b.where() + " " + p);
                }
                shells += SHELLS.contains(b.info().split("\\s+")[0]) ? 1 : 0;
            }
            bad.addAll(indentedCommands(doc));
        }
        assertThat(bad).as("docs code blocks (docs/README.md, 'Code blocks')").isEmpty();
        assertThat(shells).as("shell blocks found (the scan works)").isGreaterThan(10);
    }

    @Test
    void theCheckCatchesWhatItShould() {
        Path f = Path.of("x.md");
        assertThat(problem(new Block(f, 1, "", List.of("anything")))).contains("no info string");
        assertThat(problem(new Block(f, 1, "sh", List.of("./ripv cli --exec '?services'")))).contains("neither runnable");
        assertThat(problem(new Block(f, 1, "sh", List.of("# needs real hardware: a glider on /dev/ttyUSB0",
                "./ripv service serial --link /dev/ttyUSB0")))).isNull();
        assertThat(problem(new Block(f, 1, "sh runnable", List.of("./ripv cli --exec '?services'")))).isNull();
        assertThat(problem(new Block(f, 1, "text", List.of("./ripv cli --exec '?services'")))).contains("make it an sh block");
        assertThat(problem(new Block(f, 1, "text", List.of("ripv> ?status sim01", "sim01: on call")))).isNull();
        assertThat(problem(new Block(f, 1, "synopsis", List.of("./ripv bench calls [--vehicles 100]")))).isNull();
    }
}
