package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.function.Supplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.Transfer;
import org.ripv.it.TestSystem;
import org.ripv.messages.FileListing;

/**
 * The GUI's file actions against a real server, headless: an upload of a taken name is refused and
 * marked for the keep/replace question; "keep both" stores it under a new name; Delete removes a
 * file and the FIM lists follow.
 */
class FimDeleteAndClashTest {
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    Path dir;
    TestSystem sys;
    ExecutorService ui;
    ClientModel model;
    GuiManager manager;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        ui = Executors.newSingleThreadExecutor(r -> new Thread(r, "test-ui"));
        model = new ClientModel();
        manager = new GuiManager(model, ui, ClientSocketHandler::connect,
                new GuiManager.Timings(Duration.ofSeconds(15), Duration.ofMillis(200), Duration.ofSeconds(1)));
        manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray())
                .get(T.toMillis(), TimeUnit.MILLISECONDS);
    }

    @AfterEach
    void stop() {
        if (manager != null) {
            manager.close();
        }
        if (ui != null) {
            ui.shutdownNow();
        }
        if (sys != null) {
            sys.close();
        }
    }

    <V> V onUi(Callable<V> c) throws Exception {
        return ui.submit(c).get(T.toMillis(), TimeUnit.MILLISECONDS);
    }

    <V> V await(String what, Supplier<V> value, Predicate<V> ok) throws Exception {
        long end = System.nanoTime() + T.toNanos();
        while (true) {
            V v = onUi(value::get);
            if (ok.test(v)) {
                return v;
            }
            if (System.nanoTime() > end) {
                throw new AssertionError("timed out waiting for " + what + "; last: " + v);
            }
            Thread.sleep(50);
        }
    }

    List<String> uploads() {
        return model.directory(FileArea.UPLOAD).files().stream().map(FileListing.Entry::name).toList();
    }

    @Test
    void aTakenNameIsAskedAboutKeepBothStoresASecondAndDeleteRemovesOne() throws Exception {
        Path local = Files.writeString(dir.resolve("plan.ma"), "behavior: dive\n");
        Transfer first = onUi(() -> manager.upload(local));
        await("the first upload", () -> first.state(), s -> s == Transfer.State.DONE);
        Transfer second = onUi(() -> manager.upload(local));
        await("the second upload refused", () -> second.state(), s -> s == Transfer.State.FAILED);
        assertThat(onUi(second::nameTaken)).as("FILE_EXISTS marks it for the question").isTrue();
        assertThat(onUi(second::claimQuestion)).isTrue();

        Transfer kept = onUi(() -> manager.upload(local, ClientSocketHandler.IfExists.KEEP));
        await("keep both", () -> kept.state(), s -> s == Transfer.State.DONE);
        List<String> both = await("two plan files listed", this::uploads,
                n -> n.stream().filter(f -> f.startsWith("plan")).count() == 2);
        String other = both.stream().filter(f -> f.startsWith("plan") && !f.equals("plan.ma")).findFirst().orElseThrow();

        onUi(() -> {
            manager.deleteFile(other);
            return null;
        });
        await("the deleted file gone from FIM", this::uploads, n -> !n.contains(other) && n.contains("plan.ma"));
        assertThat(sys.uploadDir().resolve(other)).doesNotExist();
        assertThat(onUi(model::noticeIsError)).as(onUi(model::noticeDetail)).isFalse();
    }
}
