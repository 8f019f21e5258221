package org.ripv.server.workflow;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.util.Optional;
import java.util.Properties;
import org.ripv.server.store.StateStore;

/**
 * Which files of each vehicle a workflow has fetched, by name and size, so that
 * {@code ymodem:get *.DBD} fetches only what is new. Kept in the server's {@link StateStore}
 * (embedded: one owner-only file per MailBox in {@code DATA/workflows/fetched/}).
 */
final class FetchedFiles {
    private final StateStore store;

    FetchedFiles(StateStore store) {
        this.store = store;
    }

    private Properties read(String mailbox) throws IOException {
        Properties p = new Properties();
        Optional<String> text = store.loadFetched(mailbox);
        if (text.isPresent()) {
            p.load(new StringReader(text.get()));
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
        store.saveFetched(mailbox, w.toString());
    }
}
