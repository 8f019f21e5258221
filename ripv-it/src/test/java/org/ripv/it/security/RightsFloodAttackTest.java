package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URLEncoder;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.it.web.WebVisitor;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.ServerConfig;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * {@code GET /api/rights} answers what the permit file lets a user send; each question is up to 16
 * commands of 300 characters, matched against every rule. A logged-in observer who asks the largest
 * questions as fast as eight threads can gets the same true answers, an over-large one a clear 400
 * and never a grant, and everyone else is still served meanwhile.
 */
@ResourceLock(Shared.CPU)
class RightsFloodAttackTest {
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    static Path dir;
    static TestSystem sys;
    static WebVisitor web;

    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config).user("mallory", "observers").user("bob", "operators");
        web = new WebVisitor(sys.server().httpPort(), true);
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    /** A question of {@code commands} commands of {@code length} characters, each a regex-hostile word. */
    static String question(int commands, int length) {
        return "/api/rights?m=" + IntStream.range(0, commands)
                .mapToObj(i -> ((i == 0 ? "?whoami " : "put ") + "(a*".repeat(length)).substring(0, length))
                .map(c -> "&c=" + URLEncoder.encode(c, StandardCharsets.UTF_8))
                .collect(Collectors.joining());
    }

    @Test
    void theLargestQuestionsAsFastAsPossibleGrantNothingAndStarveNobody() throws Exception {
        String mallory = web.login("mallory", TestSystem.PASSWORD);
        String biggest = question(16, 290);
        HttpResponse<String> one = web.get(biggest, "Cookie", mallory);
        assertThat(one.statusCode()).isEqualTo(200);
        String truth = one.body();
        assertThat(truth).as("an observer may not put").containsPattern("\"put \\(a\\*[^\"]*\":false")
                .doesNotContainPattern("\"put [^\"]*\":true");

        ExecutorService pool = Executors.newFixedThreadPool(8);
        ClientSocketHandler bob = sys.login("bob");
        try {
            List<Future<HttpResponse<String>>> flood = new ArrayList<>();
            for (int i = 0; i < 2_000; i++) {
                flood.add(pool.submit(() -> web.get(biggest, "Cookie", mallory)));
            }
            // While the flood runs, another user's request is answered.
            long before = System.nanoTime();
            assertThat(bob.call("", "?whoami", Priority.NORMAL, T, p -> { }).status()).isEqualTo(Status.OK);
            assertThat(Duration.ofNanos(System.nanoTime() - before)).isLessThan(T);
            for (Future<HttpResponse<String>> f : flood) {
                HttpResponse<String> r = f.get();
                assertThat(r.statusCode()).isEqualTo(200);
                assertThat(r.body()).as("the same question, the same answer").isEqualTo(truth);
            }
        } finally {
            pool.shutdownNow();
            bob.close();
        }
    }

    @Test
    void overLargeQuestionsAreRefusedClearly() throws Exception {
        String mallory = web.login("mallory", TestSystem.PASSWORD);
        HttpResponse<String> many = web.get(question(17, 20), "Cookie", mallory);
        assertThat(many.statusCode()).isEqualTo(400);
        assertThat(many.body()).contains("at most 16 commands of at most 300 characters");
        String longWord = "/api/rights?m=&c=" + "x".repeat(301);
        assertThat(web.get(longWord, "Cookie", mallory).statusCode()).isEqualTo(400);
        // A megabyte of query string never reaches the handler.
        int huge = web.get("/api/rights?m=&c=" + "x".repeat(1 << 20), "Cookie", mallory).statusCode();
        assertThat(huge).isIn(400, 414, 431);
        assertThat(web.get(question(1, 20)).statusCode()).as("nobody logged in").isEqualTo(401);
        assertThat(web.get(question(1, 20), "Cookie", mallory).statusCode()).as("still serving").isEqualTo(200);
    }
}
