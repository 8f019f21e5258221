package org.ripv.client.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.time.Duration;
import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.json.JsonWriter;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;

/**
 * {@code ripv cli ... --follow MAILBOX}: watches a MailBox and prints its console — the recent
 * entries the server replays, then every line, command, event and transfer as it comes — until
 * the connection ends (or Ctrl-C). With {@code --json}, one object per line with the fields that
 * apply: time, mailbox, kind, user, text, event, lat, lon.
 */
public final class ConsoleFollower implements ClientSocketHandler.Listener {
    private final ClientSocketHandler client;
    private final PrintStream out;
    private final PrintStream err;
    private final boolean json;
    private final CountDownLatch ended = new CountDownLatch(1);
    private final AtomicReference<Exception> cause = new AtomicReference<>();
    private volatile String mailbox = "";
    private volatile boolean endedByServer;

    public ConsoleFollower(ClientSocketHandler client, PrintStream out, PrintStream err, boolean json) {
        this.client = client;
        this.out = out;
        this.err = err;
        this.json = json;
    }

    /**
     * Follows until the connection ends. Returns 0 when stopped by {@link #stop}, 1 when the
     * server refused the watch or ended it (the user lost the right to read the MailBox), 3 when
     * the connection was lost.
     */
    public int follow(String address, Duration timeout) throws IOException {
        this.mailbox = address;
        client.addListener(this);
        try {
            OutgoingServerMessage r = client.call("", "?watch " + address, Priority.NORMAL, timeout, null);
            if (r.status() != Status.OK) {
                err.println("Error: " + r.footer().replyText() + " [" + r.footer().errorCode() + ", " + r.footer().serviceId() + "]");
                return CliCommand.EXIT_ERROR_REPLY;
            }
            if (!json) {
                err.println(r.footer().replyText() + "; Ctrl-C stops");
            }
            ended.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 0;
        } finally {
            client.removeListener(this);
        }
        if (endedByServer) {
            return CliCommand.EXIT_ERROR_REPLY;
        }
        Exception why = cause.get();
        if (why != null) {
            err.println("Error: " + why.getMessage());
            return CliCommand.EXIT_NO_SESSION;
        }
        return 0;
    }

    /** Ends {@link #follow} (for embedding; the command line ends by Ctrl-C). */
    public void stop() {
        ended.countDown();
    }

    @Override
    public void onReply(OutgoingServerMessage reply) {
        String fid = reply.footer().serviceId();
        boolean mine = fid.equals(Ids.FID_CONSOLE)
                || fid.equals(Ids.FID_WATCH) && reply.status() == Status.OK && reply.header().body().trim().endsWith(mailbox);
        if (mine && reply.footer().result() instanceof ConsoleBatch b && b.mailbox().equals(mailbox)) {
            synchronized (out) {
                for (ConsoleEntry e : b.entries()) {
                    out.println(json ? JsonWriter.write(toMap(e)) : toText(e));
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

    @Override
    public void onDisconnected(Exception why) {
        cause.compareAndSet(null, why);
        ended.countDown();
    }

    static Map<String, Object> toMap(ConsoleEntry e) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("time", Instant.ofEpochMilli(e.time()).toString());
        m.put("mailbox", e.mailbox());
        m.put("kind", e.kind().name().toLowerCase(Locale.ROOT));
        if (!e.user().isEmpty()) {
            m.put("user", e.user());
        }
        m.put("text", e.text());
        if (e.event() != null) {
            m.put("event", e.event().name());
        }
        if (e.lat() != null && e.lon() != null && Double.isFinite(e.lat()) && Double.isFinite(e.lon())) {
            m.put("lat", e.lat());
            m.put("lon", e.lon());
        }
        return m;
    }

    static String toText(ConsoleEntry e) {
        String t = Instant.ofEpochMilli(e.time()).toString();
        return switch (e.kind()) {
            case LINE -> t + "  " + e.text();
            case COMMAND -> t + "  " + (e.user().isEmpty() ? "" : "[" + e.user() + "] ") + "> " + e.text();
            case TRANSFER -> t + "  ~ " + e.text();
            case EVENT -> t + "  * " + e.event() + (e.user().isEmpty() ? "" : " by " + e.user())
                    + (e.text().isEmpty() ? "" : " " + e.text())
                    + (e.lat() != null && e.lon() != null ? String.format(Locale.ROOT, " (%.5f, %.5f)", e.lat(), e.lon()) : "");
        };
    }
}
