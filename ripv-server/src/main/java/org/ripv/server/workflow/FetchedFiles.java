package org.ripv.server.workflow;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;

/**
 * Which files of each vehicle a workflow has fetched, by name and size, so that
 * {@code ymodem:get *.DBD} fetches only what is new. One owner-only file per MailBox in
 * {@code DATA/workflows/fetched/}.
 */
final class FetchedFiles {
    private final Path dir;

    FetchedFiles(Path dir) throws IOException {
        this.dir = AtomicFiles.directory(dir);
    }

    private Path file(String mailbox) {
        return dir.resolve(AtomicFiles.key(mailbox) + ".properties");
    }

    private Properties read(String mailbox) throws IOException {
        Properties p = new Properties();
        Path f = file(mailbox);
        if (Files.exists(f)) {
            p.load(new StringReader(Files.readString(f, StandardCharsets.UTF_8)));
        }
        return p;
    }

    /** True when {@code name} was fetched before with this size. */
    synchronized boolean fetched(String mailbox, String name, long size) throws IOException {
        return Long.toString(size).equals(read(mailbox).getProperty(name));
    }

    synchronized void record(String mailbox, String name, long size) throws IOException {
        Properties p = read(mailbox);
        p.setProperty(name, Long.toString(size));
        StringWriter w = new StringWriter();
        p.store(w, "files fetched by workflows from " + mailbox + ": name=size");
        AtomicFiles.write(file(mailbox), w.toString());
    }
}
