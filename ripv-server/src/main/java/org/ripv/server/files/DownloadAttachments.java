package org.ripv.server.files;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.ripv.messages.Attachment;
import org.ripv.messages.ServiceDescriptor;

/**
 * Attaches download-directory files to a command whose first word is one of the service's
 * {@link ServiceDescriptor#downloadPrefixes()} ({@code ingest NAME...}, {@code vis:file NAME x=...}):
 * every argument up to the first {@code option=value} names a file, and all of them travel as one
 * {@link Attachment#bundle}.
 */
public final class DownloadAttachments {
    /** The most one command may attach, all files together. */
    static final long MAX_TOTAL = 256L * 1024 * 1024;
    static final int MAX_FILES = 1000;

    private DownloadAttachments() {}

    /** The requester's right to one file ({@link DownloadRights}). */
    @FunctionalInterface
    public interface Check {
        void check(String name) throws IOException;
    }

    /** The bundle for {@code body}, or null when its first word is no download prefix of the service. */
    public static Attachment forCommand(FileStore files, ServiceDescriptor d, String body, Check rights) throws IOException {
        if (d.downloadPrefixes().isEmpty() || !startsWithPrefix(body, d.downloadPrefixes())) {
            return null; // most commands: decided without splitting the body
        }
        String[] words = body.trim().split("\\s+");
        if (words.length < 2) {
            throw new IllegalArgumentException("'" + words[0] + "' needs the names of files in the download directory (?dlfiles)");
        }
        if (words.length - 1 > MAX_FILES) {
            throw new IllegalArgumentException("at most " + MAX_FILES + " files in one '" + words[0] + "'");
        }
        List<Attachment> out = new ArrayList<>();
        long total = 0;
        for (int i = 1; i < words.length; i++) {
            if (words[i].indexOf('=') > 0) {
                break; // options follow the names
            }
            rights.check(words[i]); // before a byte is read: the requester's right to this file
            long size = files.readDownload(words[i], 0, 0).total();
            total += size;
            if (total > MAX_TOTAL) {
                throw new FileTooLargeException("the files named come to more than " + MAX_TOTAL + " bytes; name fewer at a time");
            }
            out.add(new Attachment(words[i], files.readDownload(words[i], 0, (int) size).data()));
        }
        return Attachment.bundle(out);
    }

    /** True when the body's first word (as {@code trim().split("\\s+")} finds it) is one of the prefixes, ignoring case. */
    private static boolean startsWithPrefix(String body, List<String> prefixes) {
        int from = 0;
        while (from < body.length() && body.charAt(from) <= ' ') {
            from++;
        }
        int to = from;
        while (to < body.length() && " \t\n\u000B\f\r".indexOf(body.charAt(to)) < 0) {
            to++;
        }
        String first = body.substring(from, to).toLowerCase(Locale.ROOT);
        return prefixes.stream().anyMatch(p -> p.toLowerCase(Locale.ROOT).equals(first));
    }
}
