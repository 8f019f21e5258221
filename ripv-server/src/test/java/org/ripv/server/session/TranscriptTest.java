package org.ripv.server.session;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.time.LocalDate;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;

class TranscriptTest {
    static final String BOX = "<SerialPortServer>::<shore>ru29";

    @TempDir
    Path dir;

    private static ConsoleEntry line(long time, String text) {
        return new ConsoleEntry(time, BOX, ConsoleEntry.Kind.LINE, "", text, null, null, null);
    }

    @Test
    void filesRotateBySizeAndHistoryReadsAcrossThem() throws Exception {
        long t0 = Instant.parse("2026-11-23T10:00:00Z").toEpochMilli();
        try (Transcript t = new Transcript(dir, 8192, 90)) {
            for (int i = 0; i < 500; i++) {
                t.append(line(t0 + i, "line " + i + " " + "z".repeat(50)));
            }
            t.sync();
            List<Path> files = t.files(t.dirOf(BOX));
            assertThat(files.size()).isGreaterThan(3);
            assertThat(files.get(0).getFileName().toString()).isEqualTo("2026-11-23.jsonl");
            assertThat(files.get(1).getFileName().toString()).isEqualTo("2026-11-23.1.jsonl");
            for (Path f : files) {
                assertThat(Files.size(f)).isLessThanOrEqualTo(8192);
            }
            Transcript.Page last = t.history(BOX, null, 3);
            assertThat(last.entries()).extracting(e -> e.text().split(" ")[1]).containsExactly("497", "498", "499");
            assertThat(last.more()).isTrue();
            Transcript.Page since = t.history(BOX, Instant.ofEpochMilli(t0 + 490), 0);
            assertThat(since.entries()).hasSize(10);
            assertThat(since.more()).isFalse();
            Transcript.Page all = t.history(BOX, Instant.ofEpochMilli(t0), 0);
            assertThat(all.entries()).hasSize(500);
        }
    }

    @Test
    void daysGoToTheirOwnFilesAndOldOnesArePruned() throws Exception {
        long old = Instant.parse("2026-01-01T12:00:00Z").toEpochMilli();
        long recent = Instant.parse("2026-11-20T12:00:00Z").toEpochMilli();
        try (Transcript t = new Transcript(dir, 1 << 20, 90)) {
            t.append(line(old, "old"));
            t.append(line(recent, "recent"));
            t.sync();
            assertThat(t.files(t.dirOf(BOX))).extracting(p -> p.getFileName().toString())
                    .containsExactly("2026-01-01.jsonl", "2026-11-20.jsonl");
            t.append(line(recent + 1, "switches files so the old one is closed"));
            t.sync();
            t.prune(LocalDate.parse("2026-11-23"));
            assertThat(t.files(t.dirOf(BOX))).extracting(p -> p.getFileName().toString()).containsExactly("2026-11-20.jsonl");
        }
    }

    @Test
    void unreadableLinesAreSkippedAndCounted() throws Exception {
        long t0 = Instant.parse("2026-11-23T10:00:00Z").toEpochMilli();
        try (Transcript t = new Transcript(dir, 1 << 20, 90)) {
            t.append(line(t0, "good one"));
            t.sync();
            Path f = t.files(t.dirOf(BOX)).get(0);
            Files.write(f, "{not json\n\u0000\u0001binary\n".getBytes(StandardCharsets.UTF_8), StandardOpenOption.APPEND);
            t.append(line(t0 + 1, "good two"));
            Transcript.Page p = t.history(BOX, null, 10);
            assertThat(p.entries()).extracting(ConsoleEntry::text).containsExactly("good one", "good two");
            assertThat(p.unreadable()).isEqualTo(2);
        }
    }

    @Test
    void mailboxDirectoriesAreSafeNamesEvenForHostileAddresses() throws Exception {
        try (Transcript t = new Transcript(dir, 1 << 20, 90)) {
            Path d = t.dirOf("<S>::<../../etc>passwd");
            assertThat(d.getParent()).isEqualTo(dir);
            assertThat(d.getFileName().toString()).matches("[A-Za-z0-9._-]+-[0-9a-f]{8}").doesNotContain("/");
            assertThat(t.dirOf("<S>::<h>a")).isNotEqualTo(t.dirOf("<S>::<h>A"));
        }
    }
}
