package org.ripv.services.ingest;

import java.io.IOException;

/** An ingest stopped before its file was stored — over a limit or cancelled ({@code ?cancel}); nothing of the file is stored. */
public final class IngestStopped extends IOException {
    private static final long serialVersionUID = 1L;
    private final boolean cancelled;

    private IngestStopped(String message, boolean cancelled) {
        super(message);
        this.cancelled = cancelled;
    }

    /** The file is over a limit (rows): it is refused. */
    static IngestStopped overLimit(String message) {
        return new IngestStopped(message, false);
    }

    /** A {@code ?cancel} stopped it. */
    static IngestStopped onCancel(String message) {
        return new IngestStopped(message, true);
    }

    /** True for a {@code ?cancel}, false for a limit. */
    public boolean cancelled() {
        return cancelled;
    }
}
