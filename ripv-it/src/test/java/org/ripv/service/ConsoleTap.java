package org.ripv.service;

import java.util.List;
import org.ripv.messages.ConsoleEntry;

/**
 * Lets a test publish console entries for a service's MailBoxes through the service's real
 * link to the server (RMI {@code console}), as the vehicle side will once it reports calls
 * (issue 11): the server cannot tell these from the service's own.
 */
public final class ConsoleTap {
    private ConsoleTap() {}

    /** Sends entries now, synchronously, over the service's connection to its server. */
    public static void publish(RIPVService service, ConsoleEntry... entries) throws Exception {
        service.sink().console(List.of(entries));
    }
}
