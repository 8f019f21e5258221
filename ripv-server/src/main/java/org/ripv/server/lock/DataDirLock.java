package org.ripv.server.lock;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import org.ripv.naming.Handles;

/**
 * The lock a RIPVServer holds on its data directory for as long as it runs: an OS file lock
 * ({@link FileChannel#tryLock()}) on {@value #FILE_NAME}, which says who holds it (pid, host,
 * since when). The operating system releases it when the process ends, however it ends, so a
 * server killed with {@code kill -9} leaves no lock behind; the text left in the file is then
 * only history, never trusted.
 */
public final class DataDirLock implements AutoCloseable {
    public static final String FILE_NAME = "server.lock";

    /** The directory is held by another process (or another server in this one). */
    public static final class HeldException extends IOException {
        private final String holder;

        HeldException(Path dir, String holder) {
            super("the data directory " + dir + " is in use by " + holder
                    + "; stop that server first, or give this one another --data DIR");
            this.holder = holder;
        }

        /** Who holds it, as its lock file says ("process 1234 on host h since ..."). */
        public String holder() {
            return holder;
        }
    }

    private final Path file;
    /** Held on the lock file's channel, which {@link FileLock#channel()} gives back to close. */
    private final FileLock lock;

    private DataDirLock(Path file, FileLock lock) {
        this.file = file;
        this.lock = lock;
    }

    /**
     * Takes the lock on {@code dir} (created if missing), or fails with {@link HeldException}
     * naming the holder; nothing else in the directory is touched either way.
     */
    public static DataDirLock acquire(Path dir) throws IOException {
        Files.createDirectories(dir);
        Path file = dir.resolve(FILE_NAME);
        FileChannel channel = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.READ, StandardOpenOption.WRITE);
        FileLock lock;
        try {
            lock = channel.tryLock();
        } catch (OverlappingFileLockException e) {
            lock = null; // this JVM holds it already
        } catch (IOException e) {
            channel.close();
            throw e;
        }
        if (lock == null) {
            String holder = holder(channel);
            channel.close();
            throw new HeldException(dir.toAbsolutePath(), holder);
        }
        try {
            byte[] me = (description() + "\n").getBytes(StandardCharsets.UTF_8);
            channel.truncate(0);
            channel.write(ByteBuffer.wrap(me), 0);
            channel.force(true);
        } catch (IOException e) {
            lock.release();
            channel.close();
            throw e;
        }
        return new DataDirLock(file, lock);
    }

    /** This process as the lock file names it. */
    static String description() {
        return "process " + ProcessHandle.current().pid() + " on host " + Handles.localHost()
                + " since " + Instant.now().truncatedTo(ChronoUnit.SECONDS);
    }

    private static String holder(FileChannel channel) {
        try {
            ByteBuffer buf = ByteBuffer.allocate(1024);
            channel.read(buf, 0);
            String text = new String(buf.array(), 0, buf.position(), StandardCharsets.UTF_8).strip();
            // The holder writes its line just after taking the lock: empty only in that instant.
            return text.isEmpty() ? "another process (it is starting)" : text.lines().findFirst().orElse(text);
        } catch (IOException e) {
            return "another process";
        }
    }

    public Path file() {
        return file;
    }

    @Override
    public void close() throws IOException {
        try {
            lock.release();
        } finally {
            lock.channel().close();
        }
    }
}
