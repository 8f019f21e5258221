package org.ripv.it.ops;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The commands of the fenced code blocks marked runnable (info string {@code sh runnable}) in
 * README.md and docs/*.md: one per line, {@code \}-continued lines joined, comments and blank
 * lines left out (docs/README.md describes the marker).
 */
final class RunnableDocs {
    static final String MARKER = "runnable";

    record Command(Path file, int line, String text) {
        @Override
        public String toString() {
            return file.getFileName() + ":" + line + ": " + text;
        }
    }

    private RunnableDocs() {}

    /** The command without a trailing {@code # comment} (a {@code #} after a space, outside quotes). */
    static String withoutComment(String command) {
        char quote = 0;
        for (int i = 0; i < command.length(); i++) {
            char c = command.charAt(i);
            if (quote != 0) {
                if (c == quote) {
                    quote = 0;
                }
            } else if (c == '\'' || c == '"') {
                quote = c;
            } else if (c == '#' && i > 0 && Character.isWhitespace(command.charAt(i - 1))) {
                return command.substring(0, i);
            }
        }
        return command;
    }

    /** How many backticks (or tildes) open a fence: a block shown inside a block takes four. */
    static int fenceLength(String t) {
        int n = 0;
        while (n < t.length() && t.charAt(n) == t.charAt(0)) {
            n++;
        }
        return n;
    }

    static List<Path> documents(Path root) throws IOException {
        List<Path> docs = new ArrayList<>(List.of(root.resolve("README.md")));
        try (var s = Files.list(root.resolve("docs"))) {
            s.filter(p -> p.toString().endsWith(".md")).sorted().forEach(docs::add);
        }
        return docs;
    }

    static List<Command> commands(Path doc) throws IOException {
        List<String> lines = Files.readAllLines(doc, StandardCharsets.UTF_8);
        List<Command> out = new ArrayList<>();
        boolean inRunnable = false;
        String fence = null;
        StringBuilder pending = null;
        int pendingLine = 0;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            String t = line.strip();
            if (fence == null && (t.startsWith("```") || t.startsWith("~~~"))) {
                int n = fenceLength(t);
                fence = t.substring(0, n);
                List<String> info = List.of(t.substring(n).strip().split("\\s+"));
                inRunnable = info.contains(MARKER);
                continue;
            }
            if (fence != null && t.equals(fence)) {
                fence = null;
                inRunnable = false;
                continue;
            }
            if (!inRunnable) {
                continue;
            }
            if (pending == null && (t.isEmpty() || t.startsWith("#"))) {
                continue;
            }
            if (pending == null) {
                pending = new StringBuilder();
                pendingLine = i + 1;
            }
            boolean continued = t.endsWith("\\");
            pending.append(continued ? t.substring(0, t.length() - 1).strip() + " " : t);
            if (!continued) {
                out.add(new Command(doc, pendingLine, withoutComment(pending.toString()).strip()));
                pending = null;
            }
        }
        return out;
    }
}
