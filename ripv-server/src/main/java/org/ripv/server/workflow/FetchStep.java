package org.ripv.server.workflow;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.DigestInputStream;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Pattern;
import org.ripv.messages.FileListing;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;
import org.ripv.server.dataloop.IngestVerdict;
import org.ripv.server.files.FileNames;

/**
 * {@code ymodem:get}: lists the vehicle's files unless every name is literal and {@code all} is
 * given, picks the names and glob matches not fetched before with the same size, and fetches
 * them one file per request, so a cut call costs only the file it cut. Each file fetched is read
 * back from the download store for its size and SHA-256. The step's verdict is the transfer's:
 * a file the server's automatic ingest refused or had stored already is fetched all the same,
 * and the step is OK with that file's {@code note:} line in its output ({@link IngestVerdict}).
 */
final class FetchStep {
    private final Workflows workflows;
    private final String mailbox;
    private final StepRequests requests;

    FetchStep(Workflows workflows, String mailbox, StepRequests requests) {
        this.workflows = workflows;
        this.mailbox = mailbox;
        this.requests = requests;
    }

    Outcome run(QueuedWorkflow e, String clientId, Step step, List<String> fetchedNow, RunTally tally) throws StepStop {
        boolean globs = step.names().stream().anyMatch(DirListing::isGlob);
        Map<String, Long> listing = new LinkedHashMap<>();
        if (globs || !step.all()) {
            OutgoingServerMessage dir = requests.send(e, clientId, mailbox, DirListing.LIST_COMMAND, step.timeout());
            if (dir.status() == Status.ERROR) {
                return Outcome.failed(dir.footer().replyText(), "listing the vehicle's files failed: "
                        + dir.footer().errorCode() + ": " + dir.footer().replyText());
            }
            listing.putAll(DirListing.listing(dir.footer().replyText()));
        }
        List<String> wanted = wanted(step, listing);
        StringBuilder out = new StringBuilder();
        List<Receipt.FileRecord> files = new ArrayList<>();
        int skipped = 0;
        for (String name : wanted) {
            Long size = listing.get(name);
            try {
                if (!step.all() && size != null && workflows.fetched.fetched(mailbox, name, size)) {
                    skipped++;
                    continue;
                }
            } catch (IOException x) {
                throw new StepStop.Failed("could not read the list of fetched files: " + x.getMessage(), out.toString());
            }
            OutgoingServerMessage r = requests.send(e, clientId, mailbox, step.transferWord() + " " + name, step.timeout());
            Outcome o = Outcome.judged(step, r);
            out.append(r.footer().replyText().strip()).append('\n');
            Optional<IngestVerdict.Counts> counts = r.footer().result() instanceof FileListing
                    ? IngestVerdict.counts(r.footer().replyText()) : Optional.empty();
            if (!o.ok()) {
                return new Outcome(false, false, false, out.toString(), name + ": " + o.error(), files);
            }
            String failed = record(r, name, size, files, fetchedNow);
            if (failed != null) {
                return new Outcome(false, false, false, out.toString(), failed, files);
            }
            counts.ifPresent(c -> tally.ingested(c.ingested()));
        }
        if (wanted.isEmpty() || files.isEmpty()) {
            out.append(wanted.isEmpty() ? "no file on the vehicle matches " + String.join(" ", step.names())
                    : "nothing new: all " + skipped + " matching file(s) were fetched before with the same size");
        } else if (skipped > 0) {
            out.append(skipped).append(" file(s) skipped: fetched before with the same size");
        }
        return Outcome.ok(out.toString(), files);
    }

    /** The step's literal names and its globs' matches in the listing, each once, in order. */
    private static List<String> wanted(Step step, Map<String, Long> listing) {
        List<String> wanted = new ArrayList<>();
        for (String n : step.names()) {
            if (DirListing.isGlob(n)) {
                Pattern g = DirListing.glob(n);
                listing.keySet().stream().filter(k -> g.matcher(k).matches()).sorted().forEach(k -> {
                    if (!wanted.contains(k)) {
                        wanted.add(k);
                    }
                });
            } else if (!wanted.contains(n)) {
                wanted.add(n);
            }
        }
        return wanted;
    }

    /** Records the files one get stored (receipt, fetched list); null, or why that failed. */
    private String record(OutgoingServerMessage r, String name, Long size, List<Receipt.FileRecord> files,
                          List<String> fetchedNow) {
        List<String> stored = new ArrayList<>();
        if (r.footer().result() instanceof FileListing l) {
            l.files().forEach(f -> stored.add(f.name()));
        }
        if (stored.isEmpty()) {
            stored.add(name);
        }
        for (String s : stored) {
            try {
                Receipt.FileRecord rec = digest(s);
                files.add(rec);
                // remembered by the vehicle's name (the store may file it as HANDLE/NAME)
                String plain = s.substring(s.lastIndexOf('/') + 1);
                workflows.fetched.record(mailbox, plain, size != null && plain.equals(name) ? size : rec.size());
                if (!fetchedNow.contains(s)) {
                    fetchedNow.add(s);
                }
            } catch (IOException x) {
                return "fetched " + s + " but could not read it from the download store: " + x.getMessage();
            }
        }
        return null;
    }

    /**
     * Size and SHA-256 of a file in the download store, read back from disk. {@code name} is as
     * the reply listed it: {@code NAME} or {@code HANDLE/NAME} (the MailBox's own folder).
     */
    private Receipt.FileRecord digest(String name) throws IOException {
        Path p = workflows.host.files().downloadDir();
        for (String part : name.split("/", -1)) {
            p = p.resolve(FileNames.check(part));
        }
        MessageDigest md;
        try {
            md = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException x) {
            throw new IllegalStateException(x);
        }
        long size = 0;
        try (InputStream in = new DigestInputStream(Files.newInputStream(p), md)) {
            byte[] buf = new byte[64 * 1024];
            for (int n; (n = in.read(buf)) > 0; ) {
                size += n;
            }
        }
        return new Receipt.FileRecord(name, size, HexFormat.of().formatHex(md.digest()));
    }
}
