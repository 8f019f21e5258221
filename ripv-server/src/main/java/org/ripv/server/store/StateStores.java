package org.ripv.server.store;

import java.io.IOException;
import java.nio.file.Path;

/** Opens the store a {@link StoreLocation} names. */
public final class StateStores {
    private StateStores() {}

    /**
     * @param where               embedded, or a PostgreSQL URL with credentials
     * @param dataDir             the server's data directory (the embedded store's home)
     * @param transcriptFileBytes the embedded store's transcript file size
     */
    public static StateStore open(StoreLocation where, Path dataDir, long transcriptFileBytes) throws IOException {
        return where == null || where.isEmbedded() ? new EmbeddedStateStore(dataDir, transcriptFileBytes)
                : PostgresStateStore.open(where);
    }
}
