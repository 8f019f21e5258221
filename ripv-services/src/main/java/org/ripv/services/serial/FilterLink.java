package org.ripv.services.serial;

import java.io.IOException;

/**
 * A link over another that passes every call on to it, as {@link java.io.FilterInputStream} does
 * for streams: a subclass overrides only what it changes ({@link Connection} reads through its
 * reader thread; the glider simulator's shell pushes bytes back for the next read).
 */
public abstract class FilterLink implements Link {
    /** The link underneath. */
    protected final Link link;

    protected FilterLink(Link link) {
        this.link = link;
    }

    @Override
    public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
        return link.read(buffer, offset, len, timeoutMillis);
    }

    @Override
    public void write(byte[] buffer, int offset, int len) throws IOException {
        link.write(buffer, offset, len);
    }

    @Override
    public void flush() throws IOException {
        link.flush();
    }

    @Override
    public boolean buffersDeeply() {
        return link.buffersDeeply();
    }

    @Override
    public String describe() {
        return link.describe();
    }

    @Override
    public boolean hasCarrierLine() {
        return link.hasCarrierLine();
    }

    @Override
    public boolean carrier() {
        return link.carrier();
    }

    @Override
    public void close() {
        link.close();
    }
}
