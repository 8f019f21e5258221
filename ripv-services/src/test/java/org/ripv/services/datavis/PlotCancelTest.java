package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
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
}
