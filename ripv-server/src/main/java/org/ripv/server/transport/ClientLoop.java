package org.ripv.server.transport;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.CancelledKeyException;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One selector thread: reads its connections when they have bytes, writes the ones whose
 * replies did not fit the socket when the socket has room, and runs what other threads hand it
 * ({@link #execute}) between selects, so a connection's reading is only ever done here.
 */
final class ClientLoop implements Runnable {
    private static final Logger log = LoggerFactory.getLogger(ClientLoop.class);
    /**
     * What one read takes from a socket, shared by every connection of this loop: an idle client
     * holds no read buffer of its own (a TLS record is at most about 17 KiB; a partial one is kept
     * by its connection until the rest arrives).
     */
    static final int READ_BUFFER = 64 * 1024;

    private final Selector selector;
    private final Thread thread;
    private final Queue<Runnable> tasks = new ConcurrentLinkedQueue<>();
    private volatile boolean closed;
    final ByteBuffer netIn = ByteBuffer.allocateDirect(READ_BUFFER);
    ByteBuffer appIn = ByteBuffer.allocate(READ_BUFFER);

    ClientLoop(String name) throws IOException {
        selector = Selector.open();
        thread = new Thread(this, name);
        thread.setDaemon(true);
        thread.start();
    }

    Selector selector() {
        return selector;
    }

    boolean inLoop() {
        return Thread.currentThread() == thread;
    }

    /** Runs {@code task} on this loop's thread (at once when already there). */
    void execute(Runnable task) {
        if (inLoop()) {
            task.run();
            return;
        }
        tasks.add(task);
        selector.wakeup();
    }

    @Override
    public void run() {
        try {
            while (!closed) {
                selector.select();
                for (Runnable t = tasks.poll(); t != null; t = tasks.poll()) {
                    run(t);
                }
                for (SelectionKey key : selector.selectedKeys()) {
                    Connection c = (Connection) key.attachment();
                    try {
                        if (key.isValid() && key.isWritable()) {
                            c.writable();
                        }
                        if (key.isValid() && key.isReadable()) {
                            c.readable();
                        }
                    } catch (CancelledKeyException e) {
                        // closed meanwhile by another thread: nothing more to do for it
                    }
                }
                selector.selectedKeys().clear();
            }
        } catch (IOException | ClosedSelectorException e) {
            if (!closed) {
                log.error("{} stopped: {}", thread.getName(), e.toString());
            }
        }
    }

    private void run(Runnable task) {
        try {
            task.run();
        } catch (RuntimeException e) {
            log.error("{}: a task failed", thread.getName(), e);
        }
    }

    void close() {
        closed = true;
        try {
            selector.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }
}
