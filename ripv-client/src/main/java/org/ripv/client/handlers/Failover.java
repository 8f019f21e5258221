package org.ripv.client.handlers;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Consumer;
import org.ripv.failover.ServerList;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Connects to whichever server of a list answers ({@code --server host1,host2}: an active server
 * and its standbys, which listen on nothing until they take over). It starts with the server
 * that answered last time; a server that failed last time goes after those that did not, and of
 * those that failed, the quickest to fail goes first: a standby refuses at once (its host is up,
 * nothing listens yet), while a cut-off host costs the whole connect deadline.
 */
public final class Failover {
    private static final Logger log = LoggerFactory.getLogger(Failover.class);
    /**
     * How long each server of a list may take to accept the connection: a dead or cut-off one
     * must not hold up the others for the usual 10 s (the TLS handshake still gets 10 s).
     */
    public static final Duration CONNECT = Duration.ofSeconds(3);

    /** Opens one connection. */
    @FunctionalInterface
    public interface Dialer {
        ClientSocketHandler dial(String host, int port) throws IOException;
    }

    private final ServerList servers;
    private final Consumer<String> say;
    private volatile int last;
    /** How long each server's last failed attempt took, in ms; 0 when it answered or was not tried. */
    private final long[] failedIn;

    /**
     * @param servers the servers, in order of preference
     * @param say     where "connected to the second server" lines go besides the log (null: the log only)
     */
    public Failover(ServerList servers, Consumer<String> say) {
        this.servers = servers;
        this.say = say == null ? m -> { } : say;
        this.failedIn = new long[servers.size()];
    }

    public ServerList servers() {
        return servers;
    }

    /**
     * Tries each server once, the last one that answered first. A server whose certificate has
     * changed ends the attempt at once ({@link Tls.RefusedCertificate}).
     *
     * @throws IOException naming every server tried and why each failed
     */
    public ClientSocketHandler connect(Dialer dialer) throws IOException {
        int n = servers.size();
        int from = last;
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            order.add((from + i) % n);
        }
        synchronized (failedIn) {
            order.sort(Comparator.comparingLong(i -> failedIn[i])); // stable: ties keep the rotation
        }
        List<String> failures = new ArrayList<>();
        IOException first = null;
        for (int at : order) {
            ServerList.Endpoint e = servers.get(at);
            long t0 = System.nanoTime();
            try {
                ClientSocketHandler h = dialer.dial(e.host(), e.port());
                synchronized (failedIn) {
                    failedIn[at] = 0;
                }
                last = at;
                if (!failures.isEmpty() || (n > 1 && at != 0)) {
                    String line = "connected to " + e + servers.position(at)
                            + (failures.isEmpty() ? "" : "; " + String.join("; ", failures));
                    log.info("{}", line);
                    say.accept(line);
                }
                return h;
            } catch (Tls.RefusedCertificate ex) {
                // A changed certificate is the man-in-the-middle signal, not "did not answer":
                // stop here, as ssh does, rather than hand the password to the next server.
                log.warn("{}: certificate refused; not trying the other servers of {}", e, servers);
                throw ex;
            } catch (IOException ex) {
                synchronized (failedIn) {
                    failedIn[at] = Math.max(1, (System.nanoTime() - t0) / 1_000_000);
                }
                if (first == null) {
                    first = ex;
                }
                failures.add(e + " did not answer (" + ex.getMessage() + ")");
            }
        }
        if (n == 1) {
            throw first;
        }
        throw new IOException("no server of " + servers + " answers: " + String.join("; ", failures), first);
    }
}
