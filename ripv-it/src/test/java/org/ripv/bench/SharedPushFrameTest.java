package org.ripv.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.DataFormatException;
import java.util.zip.Inflater;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.it.TestSystem;
import org.ripv.server.ServerConfig;
import org.ripv.service.ServiceConnector;

/**
 * Issue 38: pages without an extension send the very frame of a push (one object for all), pages
 * with permessage-deflate a frame of their own over the same bytes — whose deflater consumes what
 * it reads. Pages of both kinds, interleaved, watch one vehicle; every page must get every line,
 * in order and intact. Had a deflating page been given the shared frame, the pages after it would
 * get empty or cut payloads.
 */
class SharedPushFrameTest {
    static final int LINES = 300;
    private static final Pattern LINE = Pattern.compile("line-(\\d+)-(\\w+)");

    @TempDir
    Path dir;

    @Test
    void plainAndDeflatingPagesEachGetEveryLineIntact() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).plain().withPorts(0, 0, 0).withMaxClients(50);
        config = config.withSecurity(config.security().withWebPages(50));
        try (TestSystem sys = TestSystem.start(config)) {
            sys.user("watcher", "observers");
            VehicleConsoleService vehicle = new VehicleConsoleService("localhost", "ru29");
            ServiceConnector link = sys.register(vehicle);
            WebWatchers.Page page = WebBench.login(sys.server().httpPort(), "watcher", TestSystem.PASSWORD);
            List<Reader> pages = new ArrayList<>();
            try {
                for (int i = 0; i < 6; i++) {
                    pages.add(new Reader(page, vehicle.mailbox(), i % 2 == 1));
                }
                assertThat(pages.stream().filter(r -> r.deflating).count()).as("pages that negotiated permessage-deflate").isEqualTo(3);
                for (int i = 0; i < LINES; i++) {
                    vehicle.line("line-" + i + "-" + pad(i));
                    if (i % 50 == 49) {
                        Thread.sleep(20);
                    }
                }
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                while (System.nanoTime() < until && pages.stream().anyMatch(r -> r.lines.size() < LINES && r.failure == null)) {
                    Thread.sleep(50);
                }
                for (Reader r : pages) {
                    assertThat(r.failure).as((r.deflating ? "deflating" : "plain") + " page's reading").isNull();
                    List<Integer> expected = new ArrayList<>();
                    for (int i = 0; i < LINES; i++) {
                        expected.add(i);
                    }
                    assertThat(r.lines).as((r.deflating ? "deflating" : "plain") + " page's lines, in order").isEqualTo(expected);
                }
            } finally {
                pages.forEach(Reader::close);
                link.close();
                vehicle.stop();
            }
        }
    }

    /** Each line's own text, so a payload that lost or mixed bytes shows. */
    private static String pad(int i) {
        return Integer.toString(i * 7919, 36).repeat(1 + i % 9);
    }

    /** A page's socket, upgraded with or without permessage-deflate, read on a thread of its own. */
    private static final class Reader implements AutoCloseable {
        final boolean deflating;
        final List<Integer> lines = new CopyOnWriteArrayList<>();
        volatile String failure;
        private final Socket socket;

        Reader(WebWatchers.Page page, String mailbox, boolean deflate) throws IOException, DataFormatException {
            socket = new Socket(page.host(), page.port());
            socket.setSoTimeout(60_000);
            OutputStream out = socket.getOutputStream();
            DataInputStream in = new DataInputStream(socket.getInputStream());
            String upgrade = "GET /ws HTTP/1.1\r\nHost: " + page.host() + ":" + page.port() + "\r\nUpgrade: websocket\r\n"
                    + "Connection: Upgrade\r\nSec-WebSocket-Version: 13\r\nSec-WebSocket-Key: "
                    + Base64.getEncoder().encodeToString(new byte[16]) + "\r\nOrigin: " + page.origin() + "\r\nCookie: " + page.cookie()
                    + (deflate ? "\r\nSec-WebSocket-Extensions: permessage-deflate" : "") + "\r\n\r\n";
            out.write(upgrade.getBytes(StandardCharsets.US_ASCII));
            String head = WebWatchers.head(in);
            assertThat(head).startsWith("HTTP/1.1 101");
            deflating = head.toLowerCase().contains("permessage-deflate");
            out.write(WebWatchers.masked(("{\"id\":1,\"mailbox\":\"\",\"body\":\"?watch " + mailbox + "\",\"csrf\":\"" + page.csrf() + "\"}")
                    .getBytes(StandardCharsets.UTF_8)));
            out.flush();
            Inflater inflater = new Inflater(true); // one for the connection: the server may keep its context
            while (true) { // the ?watch reply, before any line is printed: each page then gets every line as a push
                String text = message(in, inflater);
                assertThat(text).as("the server closed the socket before the ?watch reply").isNotNull();
                if (text.contains("\"type\":\"reply\"") && text.contains("\"id\":1,")) {
                    assertThat(text).contains("\"status\":\"OK\"");
                    break;
                }
            }
            Thread t = new Thread(() -> read(in, inflater), "shared-frame-reader");
            t.setDaemon(true);
            t.start();
        }

        /** One message as text, or null at a close frame. */
        private static String message(DataInputStream in, Inflater inflater) throws IOException, DataFormatException {
            int b0 = in.readUnsignedByte();
            int len7 = in.readUnsignedByte() & 0x7f;
            long len = len7 == 126 ? in.readUnsignedShort() : len7 == 127 ? in.readLong() : len7;
            byte[] p = new byte[(int) len];
            in.readFully(p);
            if ((b0 & 0x0f) == 8) {
                return null;
            }
            if ((b0 & 0x80) == 0) {
                throw new IOException("a fragmented message (not expected for these sizes)");
            }
            return (b0 & 0x40) != 0 ? inflate(inflater, p) : new String(p, StandardCharsets.UTF_8);
        }

        private void read(DataInputStream in, Inflater inflater) {
            try {
                while (lines.size() < LINES) {
                    String text = message(in, inflater);
                    if (text == null) {
                        failure = "closed by the server";
                        return;
                    }
                    if (!text.contains("\"type\":\"push\"")) {
                        continue; // the ?watch reply and its replay
                    }
                    Matcher m = LINE.matcher(text);
                    int found = 0;
                    while (m.find()) {
                        int i = Integer.parseInt(m.group(1));
                        if (!m.group(2).equals(pad(i))) {
                            failure = "line " + i + " arrived as " + m.group();
                            return;
                        }
                        lines.add(i);
                        found++;
                    }
                    if (found == 0) {
                        failure = "a push with no line in it: " + text;
                        return;
                    }
                }
            } catch (IOException | DataFormatException | RuntimeException e) {
                failure = e.toString();
            } finally {
                inflater.end();
            }
        }

        private static String inflate(Inflater inflater, byte[] p) throws DataFormatException {
            byte[] in = new byte[p.length + 4];
            System.arraycopy(p, 0, in, 0, p.length);
            in[p.length + 2] = (byte) 0xff;
            in[p.length + 3] = (byte) 0xff; // RFC 7692 7.2.2: the tail the sender took off
            inflater.setInput(in);
            ByteArrayOutputStream text = new ByteArrayOutputStream();
            byte[] buf = new byte[8192];
            while (true) {
                int n = inflater.inflate(buf);
                text.write(buf, 0, n);
                if (n == 0 && (inflater.needsInput() || inflater.finished())) {
                    return text.toString(StandardCharsets.UTF_8);
                }
            }
        }

        @Override
        public void close() {
            try {
                socket.close();
            } catch (IOException ignored) {
                // closing
            }
        }
    }
}
