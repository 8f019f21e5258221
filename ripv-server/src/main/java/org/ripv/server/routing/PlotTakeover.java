package org.ripv.server.routing;

import java.util.function.Consumer;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.server.dataloop.DataLoop;

/**
 * Step 7: a plot from data ({@code vis:sql}, {@code vis:track}, …) is taken over by the server,
 * which queries the database first (org.ripv.server.dataloop) and answers it itself.
 */
record PlotTakeover(DataLoop dataLoop, Consumer<OutgoingServerMessage> outbox) implements AdmissionStep {
    @Override
    public Verdict check(Admitting a) {
        return dataLoop.plot(a.request(), a.sid(), a.address().toString(), outbox) ? Verdict.TAKEN : Verdict.PASS;
    }
}
