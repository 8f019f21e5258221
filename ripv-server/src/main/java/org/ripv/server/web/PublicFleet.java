package org.ripv.server.web;

import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * The public view ({@code --public GLOB}, off by default): what anonymous visitors may see of the
 * vehicles whose names match — a name, a call state, the last contact and a track — and nothing
 * else: no console text, no event text, no detail, no lock, no files.
 */
public interface PublicFleet {

    /**
     * One vehicle as the public sees it.
     *
     * @param name        its MailBox handle ({@code glider1})
     * @param state       {@code ON_CALL}, {@code DIVED}, {@code LOST} or {@code UNKNOWN}
     * @param lastContact epoch milliseconds, 0 for never
     * @param track       its fixes, oldest first, each {@code [lat, lon]}
     */
    record Vehicle(String name, String state, long lastContact, List<double[]> track) {
        public Vehicle {
            track = List.copyOf(track);
        }
    }

    /** The matching vehicles now; a snapshot shared by every visitor for a few seconds. */
    CompletableFuture<List<Vehicle>> vehicles();
}
