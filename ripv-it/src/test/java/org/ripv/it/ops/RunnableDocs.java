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

    /** A fenced code block: where its opening fence is (1-based), its info string, its lines. */
    record Block(Path file, int line, String info, List<String> body) {
        String where() {
            return file.getFileName() + ":" + line;
        }

        boolean runnable() {
            return List.of(info.split("\\s+")).contains(MARKER);
        }
    }

    /** The fenced code blocks of a page, in order; an unclosed one is an error. */
    static List<Block> blocks(Path doc) throws IOException {
        List<String> lines = Files.readAllLines(doc, StandardCharsets.UTF_8);
        List<Block> out = new ArrayList<>();
        String fence = null;
        String info = null;
        int start = 0;
        List<String> body = null;
        for (int i = 0; i < lines.size(); i++) {
            String t = lines.get(i).strip();
            if (fence == null && (t.startsWith("```") || t.startsWith("~~~"))) {
                int n = fenceLength(t);
                fence = t.substring(0, n);
                info = t.substring(n).strip();
                start = i + 1;
                body = new ArrayList<>();
            } else if (fence != null && t.equals(fence)) {
                out.add(new Block(doc, start, info, body));
                fence = null;
            } else if (fence != null) {
                body.add(lines.get(i));
            }
        }
        if (fence != null) {
            throw new IOException(doc.getFileName() + ": the code block opened at line " + start + " is never closed");
        }
        return out;
    }

    static List<Command> commands(Path doc) throws IOException {
        List<Command> out = new ArrayList<>();
        for (Block b : blocks(doc)) {
            if (!b.runnable()) {
                continue;
            }
            StringBuilder pending = null;
            int pendingLine = 0;
            for (int k = 0; k < b.body().size(); k++) {
                String t = b.body().get(k).strip();
                if (pending == null && (t.isEmpty() || t.startsWith("#"))) {
                    continue;
                }
                if (pending == null) {
                    pending = new StringBuilder();
                    pendingLine = b.line() + 1 + k;
                }
                boolean continued = t.endsWith("\\");
                pending.append(continued ? t.substring(0, t.length() - 1).strip() + " " : t);
                if (!continued) {
                    out.add(new Command(doc, pendingLine, withoutComment(pending.toString()).strip()));
                    pending = null;
                }
            }
        }
        return out;
    }
}
