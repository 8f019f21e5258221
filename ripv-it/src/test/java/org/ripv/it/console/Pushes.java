package org.ripv.it.console;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Predicate;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;

/** Collects the console entries pushed to one client. */
public class Pushes implements ClientSocketHandler.Listener {
    public final List<ConsoleEntry> entries = new CopyOnWriteArrayList<>();
    final List<ConsoleBatch> batches = new CopyOnWriteArrayList<>();

    public static Pushes on(ClientSocketHandler c) {
        Pushes p = new Pushes();
        c.addListener(p);
        return p;
    }

    @Override
    public void onReply(OutgoingServerMessage reply) {
        if (reply.footer().serviceId().equals(Ids.FID_CONSOLE) && reply.footer().result() instanceof ConsoleBatch b) {
            batches.add(b);
            entries.addAll(b.entries());
            synchronized (this) {
                notifyAll();
            }
        }
    }

    /** Waits until an entry matches; false at the deadline. */
    public synchronized boolean await(Predicate<ConsoleEntry> p, Duration d) throws InterruptedException {
        long end = System.nanoTime() + d.toNanos();
        while (entries.stream().noneMatch(p)) {
            long left = end - System.nanoTime();
            if (left <= 0) {
                return false;
            }
            wait(Math.max(1, left / 1_000_000));
        }
        return true;
    }

    public List<String> texts() {
        return entries.stream().map(ConsoleEntry::text).toList();
    }
}
