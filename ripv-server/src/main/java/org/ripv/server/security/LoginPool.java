package org.ripv.server.security;

import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Where password hashes are checked: a few threads (half the cores, at least one) and a short
 * queue. However many connections try to log in at once, PBKDF2 never takes more than those
 * threads' share of the CPU, so commands of users already logged in keep their speed; when the
 * queue is full a log-in is refused as busy rather than waiting without bound. Under a flood
 * (others waiting) each thread also rests as long as its last check took, so hashing takes at
 * most half of those threads' cores and commands keep the rest.
 */
public final class LoginPool implements AutoCloseable {
    /** Log-ins waiting for a thread before further ones are refused. */
    static final int QUEUE = 64;

    private final ThreadPoolExecutor pool;

    public LoginPool() {
        this(Math.max(1, Runtime.getRuntime().availableProcessors() / 2));
    }

    public LoginPool(int threads) {
        AtomicInteger n = new AtomicInteger();
        ThreadLocal<Long> started = new ThreadLocal<>();
        pool = new ThreadPoolExecutor(threads, threads, 0, TimeUnit.MILLISECONDS, new ArrayBlockingQueue<>(QUEUE), r -> {
            Thread t = new Thread(r, "ripv-login-" + n.incrementAndGet());
            t.setDaemon(true);
            t.setPriority(Thread.MIN_PRIORITY);
            return t;
        }, new ThreadPoolExecutor.AbortPolicy()) {
            @Override
            protected void beforeExecute(Thread t, Runnable r) {
                started.set(System.nanoTime());
            }

            @Override
            protected void afterExecute(Runnable r, Throwable t) {
                // The caller has its answer already; rest only while others wait (a flood).
                long spent = System.nanoTime() - started.get();
                if (!getQueue().isEmpty()) {
                    try {
                        TimeUnit.NANOSECONDS.sleep(spent);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }
            }
        };
    }

    /** The most log-ins this pool holds at once: those being checked and those waiting for a thread. */
    public int capacity() {
        return pool.getMaximumPoolSize() + QUEUE;
    }

    /** Thrown when too many log-ins wait already. */
    public static final class Busy extends Exception {
        private static final long serialVersionUID = 1L;

        Busy() {
            super("too many log-ins at once; try again in a few seconds");
        }
    }

    /** Runs a check on the pool and waits for it (the caller is a thread that may wait: {@link Logins}). */
    public <T> T run(Callable<T> check) throws Busy, InterruptedException {
        Future<T> f;
        try {
            f = pool.submit(check);
        } catch (RejectedExecutionException e) {
            throw new Busy();
        }
        try {
            return f.get(60, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            f.cancel(true);
            throw new Busy();
        } catch (ExecutionException e) {
            Throwable c = e.getCause();
            if (c instanceof RuntimeException r) {
                throw r;
            }
            throw new IllegalStateException(c);
        }
    }

    @Override
    public void close() {
        pool.shutdownNow();
    }
}
