package org.ripv.services.datavis;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.ClosedWatchServiceException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardWatchEventKinds;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.util.concurrent.CountDownLatch;

/**
 * A scriptable worker for the file exchange, told how to misbehave: FAIL answers {@code 0 message},
 * GARBLE writes a JPEG that is not one, NO_JPEG claims success without a picture, STALE writes
 * ok.dat without consuming data.dat (as a worker of an abandoned request would), THESIS_ORDER
 * plots but writes ok.dat before deleting the inputs, as appendix D's original script did.
 */
final class FakeWorker implements AutoCloseable {
    enum Mode { FAIL, GARBLE, NO_JPEG, STALE, THESIS_ORDER }

    private final Path dir;
    private final Mode mode;
    private final WatchService watch;
    private final Thread thread;
    final CountDownLatch handled = new CountDownLatch(1);

    FakeWorker(Path dir, Mode mode) throws IOException {
        this.dir = dir;
        this.mode = mode;
        this.watch = FileSystems.getDefault().newWatchService();
        dir.register(watch, StandardWatchEventKinds.ENTRY_CREATE, StandardWatchEventKinds.ENTRY_DELETE);
        thread = new Thread(this::run, "fake-worker-" + mode);
        thread.setDaemon(true);
        thread.start();
    }

    private void run() {
        Path data = dir.resolve(Exchange.DATA);
        Path info = dir.resolve(Exchange.INFO);
        try {
            while (handled.getCount() > 0) {
                if (Files.exists(data) && Files.exists(info)) {
                    String out = Exchange.firstLine(info).orElse("x");
                    switch (mode) {
                        case FAIL -> ok("0 the plot engine exploded");
                        case GARBLE -> {
                            Files.writeString(dir.resolve(out + ".jpg"), "not a picture");
                            ok("1");
                        }
                        case NO_JPEG -> ok("1");
                        case THESIS_ORDER -> {
                            Exchange.writeAtomically(dir, out + ".jpg", PlotRenderer.render(data).jpeg());
                            Exchange.writeAtomically(dir, Exchange.OK, "1\n".getBytes(StandardCharsets.UTF_8));
                            while (Files.exists(dir.resolve(Exchange.OK))) { // a slow script: inputs go after the service looked
                                WatchKey k = watch.take();
                                k.pollEvents();
                                k.reset();
                            }
                            Files.deleteIfExists(data);
                            Files.deleteIfExists(info);
                        }
                        case STALE -> {
                            Exchange.writeAtomically(dir, Exchange.OK, "1\n".getBytes(StandardCharsets.UTF_8));
                            handled.countDown();
                            return;
                        }
                    }
                    handled.countDown();
                    return;
                }
                WatchKey k = watch.take();
                k.pollEvents();
                k.reset();
            }
        } catch (InterruptedException | ClosedWatchServiceException | IOException | DataFormatException e) {
            // closing
        }
    }

    private void ok(String status) throws IOException {
        Files.deleteIfExists(dir.resolve(Exchange.DATA));
        Files.deleteIfExists(dir.resolve(Exchange.INFO));
        Exchange.writeAtomically(dir, Exchange.OK, (status + "\n").getBytes(StandardCharsets.UTF_8));
    }

    @Override
    public void close() throws IOException {
        thread.interrupt();
        watch.close();
    }
}
