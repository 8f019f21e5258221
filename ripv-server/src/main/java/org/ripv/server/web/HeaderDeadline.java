package org.ripv.server.web;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.eclipse.jetty.io.Connection;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.server.internal.HttpConnection;
import org.eclipse.jetty.util.Callback;

/**
 * The header deadline (issue 23 item 6): a connection must finish its first request's headers
 * within a few seconds of opening, or it is closed — however slowly it trickles bytes to dodge the
 * idle timeout. Waiting connections hold no thread (Jetty reads without blocking), so a thousand
 * slow ones cost memory only until their deadline, and everyone else is served meanwhile.
 */
final class HeaderDeadline extends Handler.Wrapper implements Connection.Listener {
    private final long millis;
    private final ScheduledExecutorService timer;
    private final Map<Connection, ScheduledFuture<?>> waiting = new ConcurrentHashMap<>();

    HeaderDeadline(Handler next, long millis, ScheduledExecutorService timer) {
        super(next);
        this.millis = millis;
        this.timer = timer;
    }

    @Override
    public void onOpened(Connection connection) {
        if (!(connection instanceof HttpConnection)) {
            return; // the TLS layer beneath: closing the HTTP connection's end point closes it too
        }
        waiting.put(connection, timer.schedule(() -> {
            if (waiting.remove(connection) != null) {
                connection.getEndPoint().close(new TimeoutException("no request headers within " + millis + " ms"));
            }
        }, millis, TimeUnit.MILLISECONDS));
    }

    @Override
    public void onClosed(Connection connection) {
        ScheduledFuture<?> f = waiting.remove(connection);
        if (f != null) {
            f.cancel(false);
        }
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) throws Exception {
        // Headers are complete once a request is handled; later ones on the connection meet the idle timeout.
        ScheduledFuture<?> f = waiting.remove(request.getConnectionMetaData().getConnection());
        if (f != null) {
            f.cancel(false);
        }
        return super.handle(request, response, callback);
    }
}
