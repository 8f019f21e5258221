package org.ripv.it;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.Tls;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;

/**
 * What the multi-host test runs inside a network namespace besides the real programs: a client
 * that times requests, polls {@code ?services}, measures round trips, and a bare TCP echo for the
 * baseline. Prints one line per finding, for the test to read:
 * <pre>
 * requests HOST:PORT USER PASS 'MAILBOX|BODY'...   REPLY i elapsedMs STATUS CODE text
 * watch HOST:PORT USER PASS NAME SECONDS            READY, then SEEN epochMs text
 * rtt HOST:PORT USER PASS N MAILBOX BODY            RTT ping medianUs p90Us / RTT request medianUs p90Us
 * echo-server PORT                                  READY; echoes 8-byte frames forever
 * tcp-rtt HOST PORT N                               RTT tcp medianUs p90Us
 * takeover H1:P,H2:P USER PASS SECONDS              ANSWER epochMs server, each time another server answers ?ping
 * </pre>
 * HOST:PORT may be a list ({@code h1:4444,h2:4444}): the first that answers.
 */
public final class NetProbe {
    private NetProbe() {}

    public static void main(String[] a) throws Exception {
        switch (a[0]) {
            case "requests" -> requests(a);
            case "watch" -> watch(a);
            case "rtt" -> rtt(a);
            case "echo-server" -> echoServer(Integer.parseInt(a[1]));
            case "tcp-rtt" -> tcpRtt(a[1], Integer.parseInt(a[2]), Integer.parseInt(a[3]));
            case "takeover" -> takeover(a);
            default -> throw new IllegalArgumentException(a[0]);
        }
        System.exit(0);
    }

    private static ClientSocketHandler login(String server, String user, String password) throws Exception {
        // Each run's server has a new certificate: trust it in a file of this probe's own, not ~/.ripv/known_hosts.
        if (System.getProperty(Tls.KNOWN_HOSTS_PROPERTY) == null) {
            java.nio.file.Path known = java.nio.file.Files.createTempFile("ripv-probe-known-hosts", "");
            known.toFile().deleteOnExit();
            System.setProperty(Tls.KNOWN_HOSTS_PROPERTY, known.toString());
        }
        ClientSocketHandler c;
        if (server.indexOf(',') >= 0) {
            c = ClientSocketHandler.connect(server, 4444);
        } else {
            String[] hp = server.split(":");
            c = ClientSocketHandler.connect(hp[0], Integer.parseInt(hp[1]));
        }
        c.login(user, password.toCharArray());
        return c;
    }

    private static String oneLine(String s) {
        return s == null ? "" : s.replace('\n', ' ').replace('\r', ' ');
    }

    private static void requests(String[] a) throws Exception {
        try (ClientSocketHandler c = login(a[1], a[2], a[3])) {
            List<CompletableFuture<OutgoingServerMessage>> fs = new ArrayList<>();
            List<Long> starts = new ArrayList<>();
            List<String> specs = Arrays.asList(a).subList(4, a.length);
            for (String spec : specs) {
                int bar = spec.indexOf('|');
                starts.add(System.nanoTime());
                fs.add(c.send(spec.substring(0, bar), spec.substring(bar + 1), Priority.NORMAL, null));
            }
            System.out.println("SENT " + System.currentTimeMillis());
            System.out.flush();
            List<CompletableFuture<Void>> printed = new ArrayList<>();
            for (int i = 0; i < fs.size(); i++) {
                int k = i;
                printed.add(fs.get(i).handle((m, e) -> {
                    long ms = (System.nanoTime() - starts.get(k)) / 1_000_000;
                    synchronized (System.out) {
                        System.out.println(e != null ? "REPLY " + k + " " + ms + " FAILED - " + oneLine(e.toString())
                                : "REPLY " + k + " " + ms + " " + m.footer().status() + " " + m.footer().errorCode() + " "
                                        + oneLine(m.footer().replyText()));
                        System.out.flush();
                    }
                    return null;
                }));
            }
            // Wait for the printing, not only the replies: dependents of a future run in no fixed order.
            CompletableFuture.allOf(printed.toArray(CompletableFuture[]::new)).get(300, TimeUnit.SECONDS);
        }
    }

    /**
     * A client of a server list that keeps asking {@code ?ping} (every 100 ms, reconnecting and
     * logging in again at once when the connection drops) and prints which server answers each
     * time that changes: the time a takeover takes as a client sees it.
     */
    private static void takeover(String[] a) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(Long.parseLong(a[4]));
        String last = null;
        ClientSocketHandler c = null;
        while (System.nanoTime() < end) {
            try {
                if (c == null || !c.isOpen()) {
                    c = login(a[1], a[2], a[3]);
                }
                c.call("", "?ping", Priority.NORMAL, Duration.ofSeconds(2), null);
                if (!c.server().equals(last)) {
                    last = c.server();
                    System.out.println("ANSWER " + System.currentTimeMillis() + " " + last);
                    System.out.flush();
                }
            } catch (Exception e) {
                if (c != null) {
                    c.close();
                }
                c = null;
            }
            Thread.sleep(100);
        }
        System.out.println("END");
    }

    private static void watch(String[] a) throws Exception {
        String name = a[4];
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(Long.parseLong(a[5]));
        try (ClientSocketHandler c = login(a[1], a[2], a[3])) {
            System.out.println("READY");
            System.out.flush();
            while (System.nanoTime() < end) {
                String text = c.call("", "?services", Priority.NORMAL, Duration.ofSeconds(10), null).footer().replyText();
                for (String line : text.split("\n")) {
                    if (line.contains("NOT ANSWERING") || line.contains(name + "  LOST")) {
                        System.out.println("SEEN " + System.currentTimeMillis() + " " + oneLine(text));
                        return;
                    }
                }
                Thread.sleep(100);
            }
            System.out.println("NEVER");
        }
    }

    private static void rtt(String[] a) throws Exception {
        int n = Integer.parseInt(a[4]);
        try (ClientSocketHandler c = login(a[1], a[2], a[3])) {
            long[] ping = new long[n];
            long[] req = new long[n];
            for (int i = 0; i < n + 20; i++) { // 20 to warm up
                long t0 = System.nanoTime();
                c.call("", "?ping", Priority.NORMAL, Duration.ofSeconds(10), null);
                long t1 = System.nanoTime();
                OutgoingServerMessage m = c.call(a[5], a[6], Priority.NORMAL, Duration.ofSeconds(10), null);
                long t2 = System.nanoTime();
                if (m.footer().status() == Status.ERROR) {
                    throw new IllegalStateException("request failed: " + m.footer().replyText());
                }
                if (i >= 20) {
                    ping[i - 20] = (t1 - t0) / 1000;
                    req[i - 20] = (t2 - t1) / 1000;
                }
            }
            System.out.println("RTT ping " + pct(ping, 50) + " " + pct(ping, 90));
            System.out.println("RTT request " + pct(req, 50) + " " + pct(req, 90));
        }
    }

    private static long pct(long[] v, int p) {
        long[] s = v.clone();
        Arrays.sort(s);
        return s[Math.min(s.length - 1, s.length * p / 100)];
    }

    private static void echoServer(int port) throws Exception {
        try (ServerSocket ss = new ServerSocket()) {
            ss.setReuseAddress(true);
            ss.bind(new InetSocketAddress(port));
            System.out.println("READY");
            System.out.flush();
            while (true) {
                Socket s = ss.accept();
                Thread t = new Thread(() -> {
                    try (s; DataInputStream in = new DataInputStream(s.getInputStream());
                         DataOutputStream out = new DataOutputStream(s.getOutputStream())) {
                        s.setTcpNoDelay(true);
                        while (true) {
                            out.writeLong(in.readLong());
                            out.flush();
                        }
                    } catch (Exception e) {
                        // client left
                    }
                });
                t.setDaemon(true);
                t.start();
            }
        }
    }

    private static void tcpRtt(String host, int port, int n) throws Exception {
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(host, port), 5000);
            s.setTcpNoDelay(true);
            DataOutputStream out = new DataOutputStream(s.getOutputStream());
            DataInputStream in = new DataInputStream(s.getInputStream());
            long[] v = new long[n];
            for (int i = 0; i < n + 20; i++) {
                long t0 = System.nanoTime();
                out.writeLong(i);
                out.flush();
                in.readLong();
                if (i >= 20) {
                    v[i - 20] = (System.nanoTime() - t0) / 1000;
                }
            }
            System.out.println("RTT tcp " + pct(v, 50) + " " + pct(v, 90));
        }
    }
}
