package org.ripv.server.routing;

import java.util.function.Consumer;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.server.dataloop.DataLoop;

/**
 * Step 7: a plot from data ({@code vis:sql}, {@code vis:track}, …) is taken over by the server,
 * which queries the database first (org.ripv.server.dataloop) and answers it itself.
 */
final class PlotTakeover implements AdmissionStep {
    private final DataLoop dataLoop;
    private final Consumer<OutgoingServerMessage> outbox;

    PlotTakeover(DataLoop dataLoop, Consumer<OutgoingServerMessage> outbox) {
        this.dataLoop = dataLoop;
        this.outbox = outbox;
    }

    @Override
    public Verdict check(Admitting a) {
        return dataLoop.plot(a.request(), a.sid(), a.address().toString(), outbox) ? Verdict.TAKEN : Verdict.PASS;
    }
}
