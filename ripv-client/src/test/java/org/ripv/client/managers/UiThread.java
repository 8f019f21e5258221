package org.ripv.client.managers;

import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * A stand-in for the Swing event thread in headless tests: one named thread that runs model
 * changes in order. {@link #sync()} waits until everything queued so far has run, and gives the
 * test thread a happens-before edge to read the model.
 */
final class UiThread implements Executor, AutoCloseable {
    private final ExecutorService thread = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "test-ui");
        t.setDaemon(true);
        return t;
    });

    @Override
    public void execute(Runnable command) {
        thread.execute(command);
    }

    /** Runs on the UI thread and waits. */
    void run(Runnable r) {
        get(() -> {
            r.run();
            return null;
        });
    }

    <T> T get(Callable<T> c) {
        try {
            return thread.submit(c).get(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        } catch (ExecutionException e) {
            throw new IllegalStateException(e.getCause());
        } catch (TimeoutException e) {
            throw new IllegalStateException("the UI thread did not answer in 10 s");
        }
    }

    /** Waits for everything queued so far. */
    void sync() {
        run(() -> { });
    }

    @Override
    public void close() {
        thread.shutdownNow();
    }
}
