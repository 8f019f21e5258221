package org.ripv.services.ingest;

import java.io.IOException;

/** An ingest stopped before its file was stored — over a limit or cancelled ({@code ?cancel}); nothing of the file is stored. */
public final class IngestStopped extends IOException {
    private static final long serialVersionUID = 1L;
    private final boolean cancelled;

    public IngestStopped(String message, boolean cancelled) {
        super(message);
        this.cancelled = cancelled;
    }

    /** True for a {@code ?cancel}, false for a limit. */
    public boolean cancelled() {
        return cancelled;
    }
}
