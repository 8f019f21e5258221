package org.ripv.it.security;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.function.Supplier;
import org.ripv.services.serial.TcpLink;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.serial.ymodem.YmodemSender;

/**
 * A scripted vehicle on loopback TCP: a PicoDOS-like prompt that echoes, and answers any
 * {@code ys ...} with whatever batch the test scripted, whatever it was asked for.
 */
final class HostileVehicle implements AutoCloseable {
    private final ServerSocket server;
    private final YmodemConfig ymodem;
    private final Thread thread;
    volatile Supplier<List<SendFile>> batch = List::of;

    HostileVehicle(YmodemConfig ymodem) throws IOException {
        this.ymodem = ymodem;
        this.server = new ServerSocket(0, 4, InetAddress.getLoopbackAddress());
        this.thread = new Thread(this::serve, "hostile-vehicle");
        thread.setDaemon(true);
        thread.start();
    }

    String device() {
        return "tcp://127.0.0.1:" + server.getLocalPort();
    }

    private void serve() {
        while (!server.isClosed()) {
            try (Socket s = server.accept()) {
                TcpLink link = new TcpLink(s);
                say(link, "C:\\>");
                StringBuilder line = new StringBuilder();
                byte[] one = new byte[1];
                while (true) {
                    if (link.read(one, 0, 1, 60_000) == 0) {
                        continue;
                    }
                    char c = (char) (one[0] & 0xFF);
                    link.write(one, 0, 1); // echo
                    if (c == '\r') {
                        continue;
                    }
                    if (c != '\n') {
                        line.append(c);
                        continue;
                    }
                    String cmd = line.toString().trim();
                    line.setLength(0);
                    if (cmd.startsWith("ys ")) {
                        try {
                            new YmodemSender(link, ymodem, null).sendBatch(batch.get());
                        } catch (IOException e) {
                            say(link, "\r\nsend failed: " + e.getMessage());
                        }
                    }
                    say(link, "\r\nC:\\>");
                }
            } catch (IOException e) {
                // the link went away; wait for the next one
            }
        }
    }

    private static void say(TcpLink link, String text) throws IOException {
        byte[] b = text.getBytes(StandardCharsets.ISO_8859_1);
        link.write(b, 0, b.length);
        link.flush();
    }

    @Override
    public void close() throws IOException {
        server.close();
    }
}
