package org.ripv.service;

import java.util.List;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.OutgoingServiceMessage;

/** Where a service's replies go: the server over RMI, or a test in the same JVM. */
@FunctionalInterface
public interface ReplySink {
    void reply(OutgoingServiceMessage reply) throws Exception;

    /** Several replies at once, in order; the default sends them one by one. */
    default void replies(List<OutgoingServiceMessage> replies) throws Exception {
        for (OutgoingServiceMessage r : replies) {
            reply(r);
        }
    }

    /**
     * True when the reader of this sink says itself when it has taken a page of a table
     * ({@code GenericRMIInterface.more}: the server, once the page went out to the client's
     * socket); false when taking the reply is taking the page (a test, a service in this JVM).
     */
    default boolean pacesPages() {
        return false;
    }

    /** Console entries the service published ({@code RIPVService.publish}); the default drops them. */
    default void console(List<ConsoleEntry> entries) throws Exception {
    }
}
