package org.ripv.server.paging;

import java.rmi.RemoteException;
import java.util.Optional;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Function;
import org.ripv.messages.Header;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.services.ServiceReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Relays one page of a table from a service to the client that asked ({@link #relay}), and tells the
 * service to send the next once the page is written to the client's socket. Readers inside the server
 * (its own {@code vis:} calls, workflow steps) take a page as soon as it arrives.
 *
 * <p>Threading: {@link #relay} runs on the RMI thread that brought the page; the calls back to the
 * service ({@code more}, or {@code cancel} for a client that left or stopped reading) run on two
 * threads of this relay, which end after a while without work, so a relay needs no stop.
 */
public final class PageRelay {
    private static final Logger log = LoggerFactory.getLogger(PageRelay.class);

    private final ThreadPoolExecutor calls;

    public PageRelay() {
        calls = new ThreadPoolExecutor(2, 2, 30, TimeUnit.SECONDS, new LinkedBlockingQueue<>(), r -> {
            Thread t = new Thread(r, "ripv-page-relay");
            t.setDaemon(true);
            return t;
        });
        calls.allowCoreThreadTimeOut(true);
    }

    /**
     * Sends a page on.
     *
     * @param page         the page as the client receives it (a PROGRESS reply with a TableResult)
     * @param service      the service sending the table
     * @param clients      the connected client (socket or web page) by client id
     * @param serverReads  whether the server itself reads replies to this client id (internal calls, workflows)
     * @param reply        how the server delivers a reply to its own readers
     */
    public void relay(OutgoingServerMessage page, ServiceReference service, Function<String, Optional<SocketHandler>> clients,
                      boolean serverReads, Consumer<OutgoingServerMessage> reply) {
        Header h = page.header();
        if (serverReads) {
            reply.accept(page);
            more(service, h);
            return;
        }
        Optional<SocketHandler> client = clients.apply(h.origin().clientId());
        if (client.isEmpty()) {
            log.info("client {} left while #{} sent its rows: stopping the query", h.origin().clientId(), h.messageId());
            cancel(service, h);
            return;
        }
        if (!client.get().push(page, (byte[]) null, () -> more(service, h))) {
            // Its queue is half full of what it has not read: stop the query rather than hold its rows.
            log.info("client {} is not reading the rows of #{}: stopping the query", h.origin().clientId(), h.messageId());
            cancel(service, h);
        }
    }

    private void more(ServiceReference service, Header h) {
        calls.execute(() -> {
            try {
                service.more(h);
            } catch (RemoteException | RuntimeException e) {
                log.debug("could not tell {} that #{} may send more rows: {}", service, h.messageId(), e.toString());
            }
        });
    }

    private void cancel(ServiceReference service, Header h) {
        calls.execute(() -> {
            try {
                service.cancel(h);
            } catch (RemoteException | RuntimeException e) {
                log.debug("could not stop #{} at {}: {}", h.messageId(), service, e.toString());
            }
        });
    }
}
