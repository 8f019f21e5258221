package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.Priority;
import org.ripv.server.ServerConfig;
import org.ripv.server.SessionOptions;

/**
 * Issue 23, item 14: a link printing at its rate limit for a day wrote ~5 GB of transcript. A
 * MailBox's transcript now keeps at most four files' worth a day, and a marker says what was cut.
 */
class TranscriptFloodAttackTest {
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    Path dir;

    @Test
    void aChattyVehicleFillsItsDaysCapAndNoMore() throws Exception {
        long fileBytes = 4096; // so the day's cap is 16 KiB here
        try (TestSystem sys = TestSystem.start(ServerConfig.forTests(dir.resolve("server")),
                SessionOptions.defaults().withTranscripts(fileBytes, 90))) {
            sys.user("alice", "operators");
            VehicleConsoleService vehicle = new VehicleConsoleService("localhost", "ru29");
            sys.register(vehicle);
            String chatter = "x".repeat(200);
            for (int i = 0; i < 1000; i++) { // 200 KB of lines
                vehicle.line(i + " " + chatter);
            }
            vehicle.line("the last line");
            ClientSocketHandler alice = sys.login("alice");
            String history = "";
            long end = System.nanoTime() + T.toNanos();
            while (!history.contains("reached the cap")) {
                assertThat(System.nanoTime()).as(history).isLessThan(end);
                Thread.sleep(200);
                history = alice.call("", "?history " + vehicle.mailbox() + " --last 2000", Priority.NORMAL, T, null).footer().replyText();
            }
            assertThat(history).contains("not kept (the live console still shows them)").doesNotContain("the last line");
            long stored;
            try (var all = Files.walk(sys.dataDir().resolve("transcripts"))) {
                stored = all.filter(p -> p.toString().endsWith(".jsonl")).mapToLong(p -> p.toFile().length()).sum();
            }
            assertThat(stored).as("bytes kept of 200 KB").isLessThanOrEqualTo(4 * fileBytes + 1024);
        }
    }
}
