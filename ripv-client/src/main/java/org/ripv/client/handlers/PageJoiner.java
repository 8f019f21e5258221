package org.ripv.client.handlers;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.TablePages;
import org.ripv.messages.TableResult;

/**
 * The tables of a connection's requests that arrive in pages (PROGRESS replies carrying a
 * {@link TableResult} page), by message id, joined into the final reply before any listener or
 * caller sees it ({@link TablePages}), so that everyone sees one table as before paging.
 */
final class PageJoiner {
    private final Map<Long, TablePages> pages = new ConcurrentHashMap<>();

    /** Keeps a page ({@link TablePages#isPage}) of the request it answers. */
    void add(OutgoingServerMessage page) {
        pages.computeIfAbsent(page.header().messageId(), k -> new TablePages()).add((TableResult) page.footer().result());
    }

    /** The final reply with the pages kept before it joined in front of its own rows; itself when none came. */
    OutgoingServerMessage joined(OutgoingServerMessage reply) {
        TablePages joined = pages.remove(reply.header().messageId());
        return joined == null ? reply : new OutgoingServerMessage(reply.header(), joined.join(reply.footer()));
    }

    /** Forgets every page (the connection ended). */
    void clear() {
        pages.clear();
    }
}
