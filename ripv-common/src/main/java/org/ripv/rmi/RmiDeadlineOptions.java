package org.ripv.rmi;

import org.ripv.launch.OptionChecks;
import picocli.CommandLine.Option;

/**
 * The {@code --rmi-connect-timeout} and {@code --rmi-read-timeout} options (a picocli mixin):
 * the server and every service launcher cap the RMI calls between them the same way, so the two
 * options, their defaults and their check live here once.
 */
public final class RmiDeadlineOptions {
    @Option(names = "--rmi-connect-timeout", defaultValue = "" + DeadlineSocketFactory.DEFAULT_CONNECT_MILLIS,
            paramLabel = "MS", description = "How long an RMI call between the server and a service may take to connect"
                    + " (default ${DEFAULT-VALUE} ms).")
    int connectMillis;

    @Option(names = "--rmi-read-timeout", defaultValue = "" + DeadlineSocketFactory.DEFAULT_READ_MILLIS,
            paramLabel = "MS", description = "How long an RMI call between the server and a service may wait for its answer"
                    + " (default ${DEFAULT-VALUE} ms).")
    int readMillis;

    /**
     * Caps every stub this process calls ({@link DeadlineSocketFactory#CONNECT_PROPERTY},
     * {@link DeadlineSocketFactory#READ_PROPERTY}); refuses a deadline under 1 ms.
     */
    public void apply() {
        OptionChecks.atLeast("--rmi-connect-timeout", connectMillis, 1);
        OptionChecks.atLeast("--rmi-read-timeout", readMillis, 1);
        System.setProperty(DeadlineSocketFactory.CONNECT_PROPERTY, Integer.toString(connectMillis));
        System.setProperty(DeadlineSocketFactory.READ_PROPERTY, Integer.toString(readMillis));
    }
}
