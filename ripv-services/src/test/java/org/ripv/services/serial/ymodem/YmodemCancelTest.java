package org.ripv.services.serial.ymodem;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code cancelWhen}: a cancel asked from another thread aborts with CAN CAN, and the far end hears it. */
class YmodemCancelTest {
    @TempDir
    Path dir;

    private final ExecutorService pool = Executors.newCachedThreadPool();
    private final MemoryLink[] link = MemoryLink.pair();

    @AfterEach
    void close() {
        link[0].close();
        pool.shutdownNow();
    }

    /** Sets the flag once this many bytes have gone. */
    private static TransferListener cancelAfter(long bytes, AtomicBoolean flag) {
        return new TransferListener() {
            @Override
            public void progress(FileHeader file, long done) {
                if (done >= bytes) {
                    flag.set(true);
                }
            }
        };
    }

    @Test
    void aCancelledReceiverSendsCanCanInPlaceOfAnAckAndKeepsNoFile() throws Exception {
        AtomicBoolean cancel = new AtomicBoolean();
        Future<List<FileHeader>> receiving = pool.submit(() -> new YmodemReceiver(link[1], YmodemTest.FAST, cancelAfter(20_000, cancel))
                .cancelWhen(cancel::get).receiveBatch(new DirectorySink(dir)));
        assertThatThrownBy(() -> new YmodemSender(link[0], YmodemTest.FAST, null)
                .sendBatch(List.of(SendFile.of("BIG.BIN", YmodemTest.random(200_000, 7)))))
                .isInstanceOfSatisfying(YmodemException.class, e -> assertThat(e.cancelledByPeer()).as(e.getMessage()).isTrue());
        assertThatThrownBy(() -> receiving.get(10, TimeUnit.SECONDS)).isInstanceOf(ExecutionException.class)
                .hasCauseInstanceOf(YmodemException.class).hasMessageContaining("cancelled receiving 'BIG.BIN'");
        try (var files = Files.list(dir)) {
            assertThat(files.filter(p -> !p.getFileName().toString().startsWith(".")).toList()).isEmpty();
        }
    }

    @Test
    void aCancelledSenderSendsCanCanAndTheReceiverStops() throws Exception {
        AtomicBoolean cancel = new AtomicBoolean();
        Future<List<FileHeader>> receiving = pool.submit(() -> new YmodemReceiver(link[1], YmodemTest.FAST, null)
                .receiveBatch(new DirectorySink(dir)));
        assertThatThrownBy(() -> new YmodemSender(link[0], YmodemTest.FAST, cancelAfter(20_000, cancel)).cancelWhen(cancel::get)
                .sendBatch(List.of(SendFile.of("BIG.BIN", YmodemTest.random(200_000, 8)))))
                .isInstanceOf(YmodemException.class).hasMessageContaining("cancelled sending 'BIG.BIN'");
        assertThatThrownBy(() -> receiving.get(10, TimeUnit.SECONDS)).isInstanceOf(ExecutionException.class)
                .hasCauseInstanceOf(YmodemException.class).hasMessageContaining("CAN CAN");
        assertThat(dir.resolve("BIG.BIN")).doesNotExist();
    }

    @Test
    void withoutACancelTheTransferCompletes() throws Exception {
        Future<List<FileHeader>> receiving = pool.submit(() -> new YmodemReceiver(link[1], YmodemTest.FAST, null)
                .cancelWhen(() -> false).receiveBatch(new DirectorySink(dir)));
        new YmodemSender(link[0], YmodemTest.FAST, null).cancelWhen(() -> false)
                .sendBatch(List.of(SendFile.of("OK.BIN", YmodemTest.random(50_000, 9))));
        assertThat(receiving.get(10, TimeUnit.SECONDS)).hasSize(1);
        assertThat(Files.readAllBytes(dir.resolve("OK.BIN"))).isEqualTo(YmodemTest.random(50_000, 9));
    }
}
