package org.ripv.services.database;

import java.util.function.Consumer;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;

/**
 * Tells watchers, the transcript and notification subscribers of a DatabaseServer MailBox about
 * files that wait for a sensor-list cache, besides the ingest's own reply: the reply goes only to
 * whoever fetched, while a pilot waiting for the data watches the database or subscribes to its
 * events ({@link VehicleEvent#INGEST_WAITING}, {@link VehicleEvent#INGEST_RELEASED}), and about
 * files refused or stored already ({@link VehicleEvent#INGEST_REFUSED}, {@link VehicleEvent#INGEST_REPEATED}).
 */
interface IngestNotices {
    /** Tells no one (in-process tests and tools without a server). */
    IngestNotices NONE = new IngestNotices() {
        @Override
        public void waiting(String file, String crc, String user) { }

        @Override
        public void released(String file, String crc, String outcome, String user) { }

        @Override
        public void refused(String line, String user) { }

        @Override
        public void repeated(String line, String user) { }
    };

    /** A file is kept until the cache file {@code crc}.cac arrives. */
    void waiting(String file, String crc, String user);

    /** A file that waited for {@code crc}.cac was ingested (or refused): {@code outcome} says which. */
    void released(String file, String crc, String outcome, String user);

    /** A file was refused, nothing of it stored: {@code line} is the ingest's line for it. */
    void refused(String line, String user);

    /** A file's bytes were stored already, nothing added: {@code line} is the ingest's line for it. */
    void repeated(String line, String user);

    /** Notices published as events of one MailBox (the service's {@code publish}). */
    static IngestNotices publishing(String mailbox, Consumer<ConsoleEntry> publish) {
        return new IngestNotices() {
            @Override
            public void waiting(String file, String crc, String user) {
                publish.accept(new ConsoleEntry(System.currentTimeMillis(), mailbox, ConsoleEntry.Kind.EVENT, user,
                        file + " waits for the sensor list " + crc + ".cac (ymodem:get " + crc + ".cac, or upload it"
                        + " and ingest it)", VehicleEvent.INGEST_WAITING, null, null));
            }

            @Override
            public void released(String file, String crc, String outcome, String user) {
                publish.accept(new ConsoleEntry(System.currentTimeMillis(), mailbox, ConsoleEntry.Kind.EVENT, user,
                        outcome, VehicleEvent.INGEST_RELEASED, null, null));
            }

            @Override
            public void refused(String line, String user) {
                publish.accept(new ConsoleEntry(System.currentTimeMillis(), mailbox, ConsoleEntry.Kind.EVENT, user,
                        line, VehicleEvent.INGEST_REFUSED, null, null));
            }

            @Override
            public void repeated(String line, String user) {
                publish.accept(new ConsoleEntry(System.currentTimeMillis(), mailbox, ConsoleEntry.Kind.EVENT, user,
                        line, VehicleEvent.INGEST_REPEATED, null, null));
            }
        };
    }
}
