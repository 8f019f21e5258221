package org.ripv.dac.delivery;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * What a deployment has delivered, as {@code dac:status} and {@code ?dac MAILBOX} show it: each
 * profile (its QC summary, where it stands: {@code written}, {@code sent}, {@code push failed},
 * {@code failed the check}, {@code replaced}), each segment that gave no profile and why, and the
 * newest profile. Kept in {@code FOLDER/delivery-state.json} (written whole and renamed), so a
 * restarted service shows what it did before. Guarded by {@code this}: the delivery's thread
 * changes it, any request thread reads it.
 */
final class DeliveryState {
    /** One profile file. {@code profileEnd} is the time of its last sample (s since 1970). */
    record Entry(String name, String segment, String mode, String direction, int samples, double minDbar, double maxDbar,
                 String qc, String status, String detail, double profileEnd, String written, String changed) {
        Entry with(String newStatus, String newDetail) {
            return new Entry(name, segment, mode, direction, samples, minDbar, maxDbar, qc, newStatus, newDetail, profileEnd,
                    written, Instant.now().toString());
        }
    }

    /** A segment that gave no profile (yet): refused with the reason, or waiting for a file. */
    record Note(String segment, String status, String detail, String time) {
    }

    /** What is kept on disk. */
    record Saved(List<Entry> profiles, List<Note> segments) {
    }

    static final int MAX_NOTES = 200;
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private final Path file;
    private final Map<String, Entry> profiles = new LinkedHashMap<>();
    private final Map<String, Note> segments = new LinkedHashMap<>();

    DeliveryState(Path file) throws IOException {
        this.file = file;
        if (Files.isRegularFile(file)) {
            Saved s = JSON.readValue(file.toFile(), Saved.class);
            s.profiles().forEach(e -> profiles.put(e.name(), e));
            s.segments().forEach(n -> segments.put(n.segment(), n));
        }
    }

    synchronized boolean has(String name) {
        return profiles.containsKey(name);
    }

    synchronized Entry get(String name) {
        return profiles.get(name);
    }

    synchronized void put(Entry e) throws IOException {
        profiles.put(e.name(), e);
        save();
    }

    synchronized void note(String segment, String status, String detail) throws IOException {
        segments.remove(segment);
        segments.put(segment, new Note(segment, status, detail, Instant.now().toString()));
        while (segments.size() > MAX_NOTES) {
            segments.remove(segments.keySet().iterator().next());
        }
        save();
    }

    synchronized void clearNote(String segment) throws IOException {
        if (segments.remove(segment) != null) {
            save();
        }
    }

    /** The profiles still to send: written, or whose push failed. */
    synchronized List<String> toSend() {
        return profiles.values().stream().filter(e -> e.status().equals("written") || e.status().equals("push failed"))
                .map(Entry::name).toList();
    }

    synchronized Saved snapshot() {
        return new Saved(new ArrayList<>(profiles.values()), new ArrayList<>(segments.values()));
    }

    private void save() throws IOException {
        Files.createDirectories(file.getParent());
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        JSON.writeValue(tmp.toFile(), snapshot());
        Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    /** The state as one JSON object, for {@code --json} and the web data page. */
    Map<String, Object> json(Deployment d, Instant now) {
        Saved s = snapshot();
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("glider", d.glider());
        m.put("deployment", d.file().getFileName().toString());
        m.put("destination", d.where());
        m.put("folder", d.folder().toString());
        m.put("counts", counts(s.profiles()));
        Entry newest = newest(s.profiles());
        m.put("newest_profile", newest == null ? null : newest.name());
        m.put("newest_profile_time", newest == null ? null : Instant.ofEpochMilli((long) (newest.profileEnd() * 1000)).toString());
        m.put("seconds_since_newest_profile", newest == null ? null : Duration.between(
                Instant.ofEpochMilli((long) (newest.profileEnd() * 1000)), now).toSeconds());
        m.put("seconds_since_newest_written", newest == null ? null : Duration.between(Instant.parse(newest.written()), now).toSeconds());
        m.put("profiles", s.profiles());
        m.put("segments", s.segments());
        return m;
    }

    /** The state as text: a summary line, one line a profile, one line a segment with no profile. */
    String text(Deployment d, Instant now) {
        Saved s = snapshot();
        Map<String, Integer> c = counts(s.profiles());
        StringBuilder b = new StringBuilder();
        b.append(d.glider()).append(" → ").append(d.where()).append(": ").append(s.profiles().size()).append(" profile")
                .append(s.profiles().size() == 1 ? "" : "s");
        List<String> parts = new ArrayList<>();
        c.forEach((k, v) -> parts.add(v + " " + k));
        b.append(parts.isEmpty() ? "" : " (" + String.join(", ", parts) + ")");
        Entry newest = newest(s.profiles());
        if (newest == null) {
            b.append("; no profile yet");
        } else {
            Instant t = Instant.ofEpochMilli((long) (newest.profileEnd() * 1000));
            b.append("; newest profile ").append(newest.name()).append(", its data ").append(ago(Duration.between(t, now)))
                    .append(" (").append(t).append("), written ").append(ago(Duration.between(Instant.parse(newest.written()), now)));
        }
        for (Entry e : s.profiles()) {
            b.append('\n').append(String.format(Locale.ROOT, "%s  %s %s, %d samples, %.1f to %.1f dbar%s: %s%s", e.name(),
                    e.mode(), e.direction(), e.samples(), e.minDbar(), e.maxDbar(), e.qc(), e.status(),
                    e.detail() == null || e.detail().isEmpty() ? "" : " (" + e.detail() + ")"));
        }
        for (Note n : s.segments()) {
            b.append('\n').append(n.segment()).append(": ").append(n.status()).append(": ").append(n.detail());
        }
        return b.toString();
    }

    private static Map<String, Integer> counts(List<Entry> entries) {
        Map<String, Integer> c = new LinkedHashMap<>();
        for (String k : List.of("sent", "written", "push failed", "failed the check", "replaced")) {
            int n = (int) entries.stream().filter(e -> e.status().equals(k)).count();
            if (n > 0) {
                c.put(k, n);
            }
        }
        return c;
    }

    private static Entry newest(List<Entry> entries) {
        Entry best = null;
        for (Entry e : entries) {
            if (!e.status().equals("replaced") && (best == null || e.profileEnd() >= best.profileEnd())) {
                best = e;
            }
        }
        return best;
    }

    static String ago(Duration d) {
        long s = Math.max(0, d.toSeconds());
        if (s < 120) {
            return s + " s ago";
        }
        if (s < 7200) {
            return s / 60 + " min ago";
        }
        if (s < 172_800) {
            return s / 3600 + " h ago";
        }
        return s / 86_400 + " days ago";
    }
}
