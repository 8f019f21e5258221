package org.ripv.server.workflow;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.ripv.server.store.EmbeddedStateStore;
import org.ripv.server.store.StateStore;
import org.ripv.text.Printable;

/**
 * The receipts of every run, kept in the server's {@link StateStore} (embedded: one owner-only
 * text file each in {@code DATA/workflows/receipts/MAILBOX-KEY/}).
 */
final class Receipts {
    private final StateStore store;

    /** Receipts in files of their own under {@code dir}. */
    Receipts(Path dir) throws IOException {
        this(new EmbeddedStateStore(EmbeddedStateStore.Layout.in(dir).withReceipts(dir), 1 << 20));
    }

    Receipts(StateStore store) {
        this.store = store;
    }

    /** The most receipts kept per MailBox; older ones are deleted as new runs start. */
    static final int KEEP = 1000;

    /** Stores a receipt, replacing this run's earlier one; keeps the newest {@link #KEEP} (an every-call workflow leaves one per call). */
    void write(Receipt r) throws IOException {
        // A notify text or a vehicle's reply may hold ESC, BEL or C1 (CSI, OSC): stored escaped, so `cat` of a receipt
        // file is text, never a terminal command (issue 33 item 10); line feeds and tabs stay.
        store.saveReceipt(r.mailbox, r.fileName(), Printable.escape(r.render()), KEEP);
    }

    /** The last {@code n} receipts of a MailBox, oldest first. */
    List<String> last(String mailbox, int n) throws IOException {
        return store.lastReceipts(mailbox, n);
    }
}
