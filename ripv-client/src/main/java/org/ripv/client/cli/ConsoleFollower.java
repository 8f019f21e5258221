package org.ripv.client.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.json.Json;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ConsoleFields;
import org.ripv.messages.ConsoleLines;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.retry.Backoff;
import org.ripv.text.Printable;

/**
 * {@code ripv cli ... --follow MAILBOX}: watches a MailBox and prints its console — the recent
 * entries the server replays, then every line, command, event and transfer as it comes — until
 * the connection ends (or Ctrl-C). With {@code --json}, one object per line with the fields that
 * apply: time, mailbox, kind, user, text, event, lat, lon.
 */
public final class ConsoleFollower implements ClientSocketHandler.Listener {
    /** The longest wait between two attempts to reconnect. */
    static final Duration MAX_BACKOFF = Duration.ofSeconds(10);

    private final ClientSocketHandler first;
    private final PrintStream out;
    private final PrintStream err;
    private final boolean json;
    private final Reconnect reconnect;
    private final CountDownLatch stopped = new CountDownLatch(1);
    private volatile CountDownLatch ended = new CountDownLatch(1);
    private final AtomicReference<Exception> cause = new AtomicReference<>();
    private volatile String mailbox = "";
    private volatile boolean endedByServer;
    // The server replays recent entries on every ?watch: after a reconnect, skip what was printed.
    private long lastTime = Long.MIN_VALUE;
    private final Set<ConsoleEntry> atLastTime = new HashSet<>();

    public ConsoleFollower(ClientSocketHandler client, PrintStream out, PrintStream err, boolean json) {
        this(client, out, err, json, null);
    }

    /** With {@code reconnect}, a lost connection is followed by logging in again and watching on. */
    public ConsoleFollower(ClientSocketHandler client, PrintStream out, PrintStream err, boolean json, Reconnect reconnect) {
        this.first = client;
        this.out = out;
        this.err = err;
        this.json = json;
        this.reconnect = reconnect;
    }

    /**
     * Follows until stopped, or until the connection ends when there is no way to reconnect.
     * Returns 0 when stopped by {@link #stop} or interrupted, 1 when the server refused the watch
     * or ended it (the user lost the right to read the MailBox), 3 when the connection was lost
     * (and could not be, or was not to be, made again).
     */
    public int follow(String address, Duration timeout) throws IOException {
        this.mailbox = address;
        ClientSocketHandler client = first;
        List<ClientSocketHandler> made = new ArrayList<>();
        try {
            while (true) {
                int r = watch(client, address, timeout);
                Exception why = cause.get();
                if (r != LOST) {
                    return r;
                }
                if (reconnect == null) {
                    err.println("Error: " + why.getMessage());
                    return ExitCodes.NO_SESSION;
                }
                err.println("Connection lost (" + why.getMessage() + "); logging in again...");
                client = reconnect();
                if (client == null) {
                    return 0; // stopped while waiting
                }
                made.add(client);
                err.println("Reconnected to " + client.server() + "; lines from before are in ?history " + address);
            }
        } finally {
            for (ClientSocketHandler c : made) {
                c.close();
            }
        }
    }

    private static final int LOST = -1;

    /** One watch on one connection: the exit code, or LOST. */
    private int watch(ClientSocketHandler client, String address, Duration timeout) throws IOException {
        cause.set(null);
        ended = new CountDownLatch(1);
        client.addListener(this);
        try {
            OutgoingServerMessage r;
            try {
                r = client.call("", "?watch " + address, Priority.NORMAL, timeout, null);
            } catch (IOException e) {
                if (!client.isOpen() || cause.get() != null) {
                    cause.compareAndSet(null, e);
                    return LOST;
                }
                throw e;
            }
            if (r.status() != Status.OK) {
                err.println("Error: " + r.footer().replyText() + " [" + r.footer().errorCode() + ", " + r.footer().serviceId() + "]");
                return ExitCodes.ERROR_REPLY;
            }
            if (!json) {
                err.println(Printable.escape(r.footer().replyText()) + "; Ctrl-C stops");
            }
            ended.await();
            if (stopped.getCount() == 0) {
                return 0;
            }
            if (endedByServer) {
                return ExitCodes.ERROR_REPLY;
            }
            return cause.get() != null ? LOST : 0;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 0;
        } finally {
            client.removeListener(this);
        }
    }

    /** Tries again and again, waiting longer each time (up to {@link #MAX_BACKOFF}); null when stopped. */
    private ClientSocketHandler reconnect() {
        Backoff backoff = new Backoff(Duration.ofMillis(500), MAX_BACKOFF);
        while (stopped.getCount() > 0) {
            long wait = backoff.nextMillis();
            try {
                return reconnect.connect();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return null;
            } catch (Exception e) {
                err.println("Could not log in again (" + e.getMessage() + "); next try in " + wait / 1000.0 + " s");
            }
            try {
                if (stopped.await(wait, TimeUnit.MILLISECONDS)) {
                    return null;
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return null;
            }
        }
        return null;
    }

    /** Ends {@link #follow} (for embedding; the command line ends by Ctrl-C). */
    public void stop() {
        stopped.countDown();
        ended.countDown();
    }

    @Override
    public void onReply(OutgoingServerMessage reply) {
        String fid = reply.footer().serviceId();
        boolean watched = fid.equals(Ids.FID_WATCH) && reply.status() == Status.OK;
        if (watched && reply.footer().result() instanceof ConsoleBatch b && reply.header().body().trim().endsWith(" " + b.mailbox())) {
            mailbox = b.mailbox(); // the server's full address for the name given (?watch sim01)
        }
        boolean mine = fid.equals(Ids.FID_CONSOLE) || watched && reply.header().body().trim().endsWith(mailbox);
        if (mine && reply.footer().result() instanceof ConsoleBatch b && b.mailbox().equals(mailbox)) {
            synchronized (out) {
                for (ConsoleEntry e : b.entries()) {
                    if (seen(e)) {
                        continue;
                    }
                    // a vehicle's bytes and others' text are data: escaped, never terminal controls (issue 23, item 8)
                    out.println(json ? Json.write(toMap(e)) : Printable.oneLine(toText(e)));
                }
                out.flush();
            }
            if (reply.status() == Status.ERROR && fid.equals(Ids.FID_CONSOLE)) {
                ended(); // the server ended the watch (the user lost the read right): its line above says why
            }
        }
    }

    private void ended() {
        endedByServer = true;
        ended.countDown();
    }

    /** True for an entry printed already (a replay after reconnecting); remembers the others. */
    private boolean seen(ConsoleEntry e) {
        if (e.time() < lastTime) {
            return true;
        }
        if (e.time() > lastTime) {
            lastTime = e.time();
            atLastTime.clear();
        }
        return !atLastTime.add(e);
    }

    @Override
    public void onDisconnected(Exception why) {
        cause.compareAndSet(null, why);
        ended.countDown();
    }

    static Map<String, Object> toMap(ConsoleEntry e) {
        return ConsoleFields.of(e, e.text());
    }

    static String toText(ConsoleEntry e) {
        return ConsoleLines.withInstant(e);
    }
}
