package org.ripv.messages;

import java.io.Serializable;
import java.util.List;
import java.util.Objects;

/**
 * What a service tells the server about itself when it registers (thesis: ServiceDescriptor).
 *
 * @param name             the full service name, {@code <ServiceName>::<host>}
 * @param sid              its six-digit service id
 * @param description      one line for the operator
 * @param panel            which fourth panel the client shows beside COM, MAM and FIM:
 *                         {@code "DAB"}, {@code "DAV"}, or {@code ""} for none (COM spans both rows)
 * @param attachPrefixes   command prefixes whose first argument names a file in the server's
 *                         upload directory, which the server then attaches (e.g. {@code "vis:"})
 * @param downloadPrefixes command words whose arguments all name files in the server's download
 *                         directory, which the server attaches as one {@linkplain Attachment#bundle
 *                         bundle} (e.g. {@code "ingest"}: {@code ingest NAME...})
 * @param registration     when the service began this registration attempt (epoch milliseconds,
 *                         strictly increasing per service; 0: not given). A registration that
 *                         arrives after a newer one of the same service is refused, never replaces it.
 * @param started          when this instance of the service started (epoch milliseconds; 0: not
 *                         given). A vehicle the server last heard on a call before then cannot
 *                         still be on that call through this instance: it restarted meanwhile.
 */
public record ServiceDescriptor(String name, String sid, String description, String panel,
                                List<String> attachPrefixes, List<String> downloadPrefixes, long registration,
                                long started)
        implements Serializable {
    public ServiceDescriptor {
        Objects.requireNonNull(name, "name");
        Ids.require(sid);
        description = description == null ? "" : description;
        panel = panel == null ? "" : panel;
        attachPrefixes = attachPrefixes == null ? List.of() : List.copyOf(attachPrefixes);
        downloadPrefixes = downloadPrefixes == null ? List.of() : List.copyOf(downloadPrefixes);
    }

    /** Start time not given. */
    public ServiceDescriptor(String name, String sid, String description, String panel, List<String> attachPrefixes,
                             List<String> downloadPrefixes, long registration) {
        this(name, sid, description, panel, attachPrefixes, downloadPrefixes, registration, 0);
    }

    /** A service that takes no files from the download directory, registration not stamped. */
    public ServiceDescriptor(String name, String sid, String description, String panel, List<String> attachPrefixes) {
        this(name, sid, description, panel, attachPrefixes, List.of(), 0);
    }

    /** A service that takes no files from the download directory. */
    public ServiceDescriptor(String name, String sid, String description, String panel, List<String> attachPrefixes,
                             long registration) {
        this(name, sid, description, panel, attachPrefixes, List.of(), registration);
    }

    /** Registration not stamped. */
    public ServiceDescriptor(String name, String sid, String description, String panel, List<String> attachPrefixes,
                             List<String> downloadPrefixes) {
        this(name, sid, description, panel, attachPrefixes, downloadPrefixes, 0);
    }

    /** The same service, stamped for one registration attempt. */
    public ServiceDescriptor withRegistration(long stamp) {
        return new ServiceDescriptor(name, sid, description, panel, attachPrefixes, downloadPrefixes, stamp, started);
    }

    /** The same service, with the time its instance started. */
    public ServiceDescriptor withStarted(long millis) {
        return new ServiceDescriptor(name, sid, description, panel, attachPrefixes, downloadPrefixes, registration, millis);
    }
}
