package org.ripv.services.serial;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * A command's reply keeps its first {@link ReplyReader#MAX_REPLY} characters, says how many bytes
 * it cut, and keeps the tail where the prompt is: a three-megabyte reply still ends at its prompt
 * (not at the command's deadline) and costs no more than the cap.
 */
class ReplyCapTest {
    @Test
    void anOverlongReplyIsCutInTheMiddleAndStillEndsAtItsPrompt() throws Exception {
        int body = 3 * 1024 * 1024;
        try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            CompletableFuture<Void> vehicle = CompletableFuture.runAsync(() -> {
                try (Socket s = server.accept()) {
                    OutputStream out = s.getOutputStream();
                    out.write("dir\r\n".getBytes(StandardCharsets.US_ASCII));
                    byte[] chunk = new byte[64 * 1024];
                    Arrays.fill(chunk, (byte) 'y');
                    for (int i = 0; i < body / chunk.length; i++) {
                        out.write(chunk);
                    }
                    out.write("\r\nthe end\r\nC:\\>".getBytes(StandardCharsets.US_ASCII));
                    out.flush();
                    s.getInputStream().read(); // until the reader hangs up
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            LinkSettings settings = LinkSettings.defaults("tcp://localhost:" + server.getLocalPort());
            ReplyReader reader = new ReplyReader(settings, new VehicleText(settings.prompt()));
            StringBuilder text = new StringBuilder();
            try (TcpLink link = new TcpLink(new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort()))) {
                long t0 = System.nanoTime();
                boolean closed = reader.read(link, text, 120_000, "dir");
                assertThat(closed).isFalse();
                assertThat(TimeUnit.NANOSECONDS.toSeconds(System.nanoTime() - t0)).as("ended at the prompt, not the deadline")
                        .isLessThan(100);
            }
            vehicle.get(30, TimeUnit.SECONDS);
            String reply = text.toString();
            long kept = ReplyReader.MAX_REPLY - "dir\r\n".length();
            assertThat(reply.length()).isLessThan(ReplyReader.MAX_REPLY + 1024);
            assertThat(reply).startsWith("dir\r\nyyy").contains("the end").endsWith("C:\\>");
            assertThat(reply).matches("(?s).*\\n\\[\\.\\.\\. (\\d+) bytes cut]\\n.*");
            long cut = Long.parseLong(reply.replaceAll("(?s).*\\[\\.\\.\\. (\\d+) bytes cut].*", "$1"));
            int tail = reply.length() - reply.indexOf(" bytes cut]\n") - " bytes cut]\n".length();
            assertThat(cut + kept + tail).as("every byte is kept or counted").isEqualTo(body + "\r\nthe end\r\nC:\\>".length());
            assertThat(new VehicleText(settings.prompt()).clean(reply, "dir")).endsWith("the end");
        }
    }
}
