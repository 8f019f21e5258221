package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.ClosedWatchServiceException;
import java.nio.file.FileSystems;
import java.nio.file.Path;
import java.nio.file.WatchService;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.ImageResult;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;

/**
 * {@code ?cancel} of a plot the built-in worker is drawing: the request ends CANCELLED at once,
 * the worker is stopped (its plot dropped), and the next plot gets a new worker and its own JPEG.
 */
class PlotCancelTest {
    @TempDir
    Path tmp;

    @Test
    void aPlotBeingDrawnIsCancelledAndTheNextGetsAFreshWorker() throws Exception {
        StringBuilder big = new StringBuilder(16_000_000);
        for (int i = 0; i < 1_000_000; i++) {
            big.append(i).append(' ').append(String.format(Locale.ROOT, "%.3f", Math.sin(i / 1000.0))).append('\n');
        }
        try (VisHarness h = new VisHarness(DataVisServer.Config.of(tmp))) {
            long id = h.send("vis:big.dat", "big.dat", big.toString());
            h.awaitProgress(id, 60); // handed to the worker, which takes seconds for a million points
            assertThat(h.cancel(id)).as("the plot is waiting for its worker: the cancel is taken").isTrue();
            // No figure in ms here (it measured the machine's load): a plot that ran to its end would
            // reply OK with a JPEG, so CANCELLED is the proof; 60 s only bounds a hang.
            OutgoingServiceMessage r = h.finalReply(id, 60);
            assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.CANCELLED);
            assertThat(r.footer().replyText()).contains("plot of big.dat cancelled");
            assertThat(h.cancel(id)).as("nothing left to cancel").isFalse();

            OutgoingServiceMessage next = h.run("vis:small.dat out=small", "small.dat", "0 1\n1 2\n2 4\n");
            assertThat(next.footer().status()).as(next.footer().replyText()).isEqualTo(Status.OK);
            ImageResult img = (ImageResult) next.footer().result();
            assertThat(img.name()).isEqualTo("small.jpg");
            VisHarness.decode(img.jpeg());
            assertThat(next.footer().replyText()).contains("3 rows");
        }
    }

    /**
     * The server shows the MailBox busy as soon as the request starts, before the plot waits on its
     * worker; a cancel in that moment was refused ("cannot stop ... while it runs"), seen in a
     * clean-clone run of VehicleCancelEndToEndTest. It is taken, and the wait that follows ends at once.
     */
    @Test
    void aCancelBeforeThePlotWaitsIsTakenAndItsWaitEndsAtOnce() throws Exception {
        PlotCancel cancel = new PlotCancel();
        assertThat(cancel.ask()).as("no request running: nothing to cancel").isFalse();
        cancel.start();
        assertThat(cancel.ask()).as("the request runs but does not wait yet").isTrue();
        assertThat(cancel.asked()).isTrue();
        try (WatchService watch = FileSystems.getDefault().newWatchService()) {
            cancel.begin(watch);
            assertThatThrownBy(watch::take).isInstanceOf(ClosedWatchServiceException.class);
        }
        cancel.end();
        assertThat(cancel.ask()).as("the request is over").isFalse();
        cancel.start();
        assertThat(cancel.asked()).as("the next request starts uncancelled").isFalse();
        try (WatchService watch = FileSystems.getDefault().newWatchService()) {
            cancel.begin(watch);
            assertThat(watch.poll()).as("its wait is open").isNull();
            assertThat(cancel.ask()).isTrue();
            assertThatThrownBy(watch::take).isInstanceOf(ClosedWatchServiceException.class);
        }
        cancel.end();
    }
}
