package org.ripv.bench;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.function.LongConsumer;

/**
 * A crowd of sockets read on a few selector threads, for the benchmarks' watchers: a thread per
 * watcher in the benchmark's own JVM on two cores would measure the clients, not the server. What a
 * frame is (RIPV's length-prefixed frames, WebSocket frames) is the subclass's; this class reads,
 * keeps a frame that a read cut off, and drops a socket at its end.
 *
 * <p>There is one thread per core, each with its share of the sockets: real watchers read on their
 * own machines, side by side; with one thread here, the server's writers finished a line while the
 * one reader still had a third of the crowd to read (docs/performance.md).
 */
abstract class SelectorReaders<C extends SelectorReaders.Socket> implements AutoCloseable {
    /** One socket: where its delays go, and the start of a frame that a read cut off, until the rest arrives. */
    static class Socket {
        final SocketChannel ch;
        final LongConsumer delays;
        volatile boolean closed;
        byte[] partial;

        Socket(SocketChannel ch, LongConsumer delays) {
            this.ch = ch;
            this.delays = delays;
        }
    }

    private final List<Loop> loops = new ArrayList<>();
    private int next;

    SelectorReaders(int threads, String name) throws IOException {
        for (int i = 0; i < Math.max(1, threads); i++) {
            loops.add(new Loop(name + "-" + i));
        }
    }

    /**
     * Takes the whole frames at the buffer's position, read at {@code now}, leaving a cut-off one
     * where it starts; false when the socket's peer said it closes.
     */
    protected abstract boolean frames(C socket, ByteBuffer b, long now) throws IOException;

    /** Reads the socket from now on, on the next thread in turn. */
    final C register(C socket) throws IOException {
        socket.ch.configureBlocking(false);
        loops.get(Math.floorMod(next++, loops.size())).register(socket);
        return socket;
    }

    /** Reads the socket from now on, on the first thread. */
    final C registerFirst(C socket) throws IOException {
        socket.ch.configureBlocking(false);
        loops.get(0).register(socket);
        return socket;
    }

    /** One selector thread and the buffer its sockets are read into, in turn. */
    private final class Loop implements Runnable {
        final Selector selector;
        volatile boolean closed;
        /**
         * One buffer for all this thread's sockets: a buffer per socket (64 KiB each, 63 MB for 990)
         * cost a copy from a temporary direct buffer and a cache miss per read, and swelled the heap
         * the benchmark reports.
         */
        ByteBuffer scratch = ByteBuffer.allocateDirect(64 * 1024);

        Loop(String name) throws IOException {
            selector = Selector.open();
            Thread thread = new Thread(this, name);
            thread.setDaemon(true);
            thread.start();
        }

        void register(C socket) throws IOException {
            synchronized (this) {
                selector.wakeup();
                socket.ch.register(selector, SelectionKey.OP_READ, socket);
            }
        }

        @Override
        @SuppressWarnings("unchecked")
        public void run() {
            while (!closed) {
                try {
                    selector.select();
                    synchronized (this) {
                        // lets register() run between selects
                    }
                    for (SelectionKey k : selector.selectedKeys()) {
                        C socket = (C) k.attachment();
                        if (!k.isValid() || !read(socket)) {
                            socket.closed = true;
                            k.cancel();
                        }
                    }
                    selector.selectedKeys().clear();
                } catch (IOException | ClosedSelectorException e) {
                    if (!closed) {
                        continue;
                    }
                }
            }
        }

        /** Reads what the socket has and takes its whole frames; false at its end. */
        private boolean read(C socket) throws IOException {
            ByteBuffer b = scratch;
            b.clear();
            if (socket.partial != null) {
                b.put(socket.partial);
                socket.partial = null;
            }
            if (socket.ch.read(b) < 0) {
                return false;
            }
            // The time of this read, not of the select: a read late in a long batch also takes
            // lines that arrived after the select returned (once timed before they were sent).
            long now = System.nanoTime();
            b.flip();
            if (!frames(socket, b, now)) {
                return false;
            }
            if (b.hasRemaining()) {
                socket.partial = new byte[b.remaining()];
                b.get(socket.partial);
                if (socket.partial.length > scratch.capacity() / 2) {
                    scratch = ByteBuffer.allocateDirect(scratch.capacity() * 2); // a large frame: grow until it fits
                }
            }
            return true;
        }

        void close() throws IOException {
            closed = true;
            for (SelectionKey k : selector.keys()) {
                k.channel().close();
            }
            selector.close();
        }
    }

    @Override
    public void close() throws IOException {
        for (Loop l : loops) {
            l.close();
        }
    }
}
