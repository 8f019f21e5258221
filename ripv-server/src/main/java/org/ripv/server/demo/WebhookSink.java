package org.ripv.server.demo;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executors;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code ripv-server.jar webhook-sink --port N}: the demo's webhook receiver. It listens on
 * loopback only and prints one line per POST ({@code TIME POST PATH BODY}) on standard output,
 * which the demo writes to {@code logs/webhooks.log}, so that {@code ?notify add webhook
 * http://127.0.0.1:N/ ...} can be tried without a service on the Internet. A body over
 * {@value #MAX_BODY} bytes is cut; anything but POST gets 405. Whatever reaches the port is
 * hostile (any local process may post): control characters are printed as a backslash, {@code u}
 * and four hex digits, so a body cannot move the cursor or recolour the terminal of a pilot reading
 * the log; and {@value #THREADS} threads serve, so a connection that never sends its request holds
 * one of them, not the sink.
 */
@Command(name = "webhook-sink", mixinStandardHelpOptions = true,
        description = "The demo's webhook receiver: prints each POST it gets on 127.0.0.1:PORT, one line each.")
public final class WebhookSink implements Callable<Integer> {
    static final int MAX_BODY = 64 * 1024;
    static final int THREADS = 4;

    @Option(names = "--port", required = true, description = "The loopback port to listen on (0: any free one).")
    int port;

    private final PrintStream out;

    public WebhookSink() {
        this(System.out);
    }

    WebhookSink(PrintStream out) {
        this.out = out;
    }

    /** Starts listening; the caller stops it. */
    HttpServer start() throws IOException {
        HttpServer server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 16);
        server.createContext("/", this::handle);
        server.setExecutor(Executors.newFixedThreadPool(THREADS, r -> {
            Thread t = new Thread(r, "ripv-webhook-sink");
            t.setDaemon(true);
            return t;
        }));
        server.start();
        return server;
    }

    @Override
    public Integer call() throws Exception {
        HttpServer server = start();
        out.println("webhook sink listening on http://127.0.0.1:" + server.getAddress().getPort() + "/");
        out.flush();
        new CountDownLatch(1).await(); // until the demo stops it
        return 0;
    }

    private void handle(HttpExchange x) throws IOException {
        try (x) {
            if (!x.getRequestMethod().equals("POST")) {
                x.sendResponseHeaders(405, -1);
                return;
            }
            byte[] body;
            try (InputStream in = x.getRequestBody()) {
                body = in.readNBytes(MAX_BODY);
            }
            String text = printable(new String(body, StandardCharsets.UTF_8).replace('\n', ' ').replace('\r', ' '));
            synchronized (out) {
                out.println(Instant.now() + " POST " + printable(x.getRequestURI().getPath()) + " " + text);
                out.flush();
            }
            x.sendResponseHeaders(204, -1);
        }
    }

    /** {@code text} with each control character (C0, DEL, C1) written as a backslash, {@code u} and four hex digits. */
    static String printable(String text) {
        StringBuilder b = new StringBuilder(text.length());
        text.codePoints().forEach(c -> {
            if (Character.getType(c) == Character.CONTROL) {
                b.append(String.format("\\u%04x", c));
            } else {
                b.appendCodePoint(c);
            }
        });
        return b.toString();
    }
}
