package org.ripv.assistants;

/** What the inbox and outbox assistants share: a name, a running flag, and how they stop. */
abstract class AssistantThread extends Thread {
    protected volatile boolean running = true;

    AssistantThread(String name) {
        super(name);
        setDaemon(true);
    }

    /**
     * Stops: interrupts what the assistant is waiting on or running (a handler blocked on a
     * device sees the interrupt and fails, which still answers its request) and waits up to the
     * given milliseconds for it to finish.
     */
    public void shutdown(long waitMillis) {
        running = false;
        interrupt();
        try {
            join(waitMillis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
