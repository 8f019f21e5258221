package org.ripv.server.web;

import java.io.IOException;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.function.Supplier;
import java.util.regex.Pattern;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;
import org.ripv.naming.MailboxAddress;
import org.ripv.naming.MalformedNameException;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.session.Transcript;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The public view's vehicles ({@code --public GLOB}): the MailBoxes the services list whose handle
 * matches the glob (the permit file's glob: {@code *} any run, case-insensitive, whole name), with
 * the call state, last contact and the fixes of the last {@link #TRACK_DAYS} days from the
 * transcript. The operator's option is the right here: anonymous visitors have no user for the
 * permit file to judge, so this reads the server's state itself and gives out only those fields.
 * One snapshot serves every visitor for {@link #FRESH}, so a crowd of visitors (or a script) costs
 * one MailBox query and one transcript read per vehicle every few seconds.
 */
public final class PublicVehicles implements PublicFleet {
    private static final Logger log = LoggerFactory.getLogger(PublicVehicles.class);
    static final Duration FRESH = Duration.ofSeconds(5);
    static final int TRACK_DAYS = 30;
    /** Fixes per vehicle at most (the newest are kept). */
    static final int MAX_FIXES = 1000;

    private final Supplier<CompletableFuture<List<String>>> addresses;
    private final ConsoleHub console;
    private final Executor checkers;
    private final Pattern names;
    private CompletableFuture<List<Vehicle>> snapshot;
    private long takenAt;

    /**
     * @param addresses the MailBoxes the services list now (never fails)
     * @param console   the vehicles' call state and transcripts
     * @param checkers  where a snapshot is read
     * @param glob      which handles are public ({@code --public GLOB})
     */
    public PublicVehicles(Supplier<CompletableFuture<List<String>>> addresses, ConsoleHub console, Executor checkers, String glob) {
        this.addresses = addresses;
        this.console = console;
        this.checkers = checkers;
        this.names = glob(glob);
    }

    /** The permit file's globs: {@code *} any run of characters, everything else literal, case-insensitive. */
    public static Pattern glob(String g) {
        if (g == null || g.isBlank() || g.chars().anyMatch(Character::isISOControl)) {
            throw new IllegalArgumentException("--public '" + g + "' is not a name glob; give e.g. 'glider*' or 'ru29'");
        }
        StringBuilder re = new StringBuilder();
        for (char c : g.strip().toCharArray()) {
            re.append(c == '*' ? ".*" : Pattern.quote(String.valueOf(c)));
        }
        return Pattern.compile(re.toString(), Pattern.CASE_INSENSITIVE | Pattern.UNICODE_CASE);
    }

    @Override
    public synchronized CompletableFuture<List<Vehicle>> vehicles() {
        long now = System.nanoTime();
        if (snapshot == null || now - takenAt > FRESH.toNanos() || snapshot.isCompletedExceptionally()) {
            takenAt = now;
            snapshot = addresses.get().thenApplyAsync(this::read, checkers);
        }
        return snapshot;
    }

    private List<Vehicle> read(List<String> addresses) {
        List<Vehicle> out = new ArrayList<>();
        for (String address : addresses) {
            String handle;
            try {
                handle = MailboxAddress.parse(address).handle();
            } catch (MalformedNameException e) {
                continue;
            }
            if (!names.matcher(handle).matches()) {
                continue;
            }
            SessionState s = console.state(address);
            out.add(new Vehicle(handle, s == null ? "UNKNOWN" : s.state().name(), s == null ? 0 : s.lastContact(), track(address)));
        }
        out.sort(Comparator.comparing(v -> v.name().toLowerCase(Locale.ROOT)));
        return out;
    }

    private List<double[]> track(String address) {
        List<double[]> fixes = new ArrayList<>();
        try {
            for (ConsoleEntry e : console.history(address, Instant.now().minus(Duration.ofDays(TRACK_DAYS)),
                    Transcript.MAX_HISTORY).entries()) {
                if (e.lat() != null && e.lon() != null) {
                    fixes.add(new double[] {e.lat(), e.lon()});
                }
            }
        } catch (IOException e) {
            log.info("public view: the transcript of {} could not be read: {}", address, e.toString());
        }
        return fixes.size() > MAX_FIXES ? fixes.subList(fixes.size() - MAX_FIXES, fixes.size()) : fixes;
    }
}
