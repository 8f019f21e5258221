package org.ripv.services.serial;

import java.time.Duration;
import java.util.Objects;
import com.google.re2j.Pattern;
import org.ripv.security.AddressRanges;

/**
 * How one link's calls and console are read (kept apart from {@link LinkSettings}, which says how
 * the link is opened and talked to).
 *
 * @param name           the MailBox handle and the vehicle's name in events ({@code ru29}), or
 *                       null for the handle the device gives ({@code tcp-host-port})
 * @param surface        on links with neither carrier nor caller, output that marks surfacing
 * @param quiet          on those links, silence this long during a call ends it (DIVED)
 * @param alert          output lines that raise an ALERT event
 * @param lineLength     console lines are cut at this many characters
 * @param linesPerSecond console lines per second the link may publish; the excess is counted
 *                       and marked "N lines skipped"
 * @param callers        on {@code listen://} links, the addresses calls are taken from
 *                       ({@code callers=CIDR[,CIDR...]}); empty: anyone who can reach the port
 * @param overdue        how often the vehicle is expected to call ({@code overdue=2h}), announced in
 *                       SURFACED for the server's OVERDUE (docs/surfacings.md); null: the server learns it
 */
public record CallSettings(String name, Pattern surface, Duration quiet, Pattern alert, int lineLength,
                           int linesPerSecond, AddressRanges callers, Duration overdue) {

    /** The Slocum surface dialog: "Glider ru29 at surface." or a GPS fix line. */
    public static final String DEFAULT_SURFACE = "Glider .* at surface|GPS Location:";
    /**
     * Lines that raise an ALERT at once: a leak or an error the vehicle shouts. Not "abort" (every
     * Slocum dialog says "Control-C to abort" and prints its ABORT HISTORY) and not sensor names
     * ({@code m_leakdetect_voltage}): the server reads each surface dialog and alerts on a new
     * abort, a leak voltage, the battery, … with the cause (docs/surfacings.md).
     */
    public static final String DEFAULT_ALERT = "LEAK|[Ll]eak detected|ERROR|[Ee]rror:";
    public static final Duration DEFAULT_QUIET = Duration.ofMinutes(10);
    public static final int DEFAULT_LINE_LENGTH = 1024;
    public static final int DEFAULT_LINES_PER_SECOND = 200;
    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");

    /** Settings whose call interval the server learns. */
    public CallSettings(String name, Pattern surface, Duration quiet, Pattern alert, int lineLength, int linesPerSecond,
                        AddressRanges callers) {
        this(name, surface, quiet, alert, lineLength, linesPerSecond, callers, null);
    }

    public CallSettings {
        if (name != null && !NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("name '" + name + "' must be 1-64 letters, digits, '.', '_' or '-',"
                    + " starting with a letter or digit");
        }
        Objects.requireNonNull(surface, "surface");
        Objects.requireNonNull(alert, "alert");
        Objects.requireNonNull(callers, "callers");
        if (quiet == null || quiet.isNegative() || quiet.isZero()) {
            throw new IllegalArgumentException("quiet time must be positive, got " + quiet);
        }
        if (lineLength < 16 || lineLength > 1 << 20) {
            throw new IllegalArgumentException("line length " + lineLength + " is outside 16-1048576");
        }
        if (linesPerSecond < 1 || linesPerSecond > 1_000_000) {
            throw new IllegalArgumentException("lines per second " + linesPerSecond + " is outside 1-1000000");
        }
    }

    /** The defaults: no name, the Slocum surface dialog, 10 minutes quiet, 1,024-character lines, 200 lines/s. */
    public static CallSettings defaults() {
        return new CallSettings(null, Pattern.compile(DEFAULT_SURFACE), DEFAULT_QUIET, Pattern.compile(DEFAULT_ALERT),
                DEFAULT_LINE_LENGTH, DEFAULT_LINES_PER_SECOND, AddressRanges.NONE);
    }

    public CallSettings withName(String newName) {
        return new CallSettings(newName, surface, quiet, alert, lineLength, linesPerSecond, callers, overdue);
    }

    public CallSettings withQuiet(Duration newQuiet) {
        return new CallSettings(name, surface, newQuiet, alert, lineLength, linesPerSecond, callers, overdue);
    }

    public CallSettings withLimits(int newLineLength, int newLinesPerSecond) {
        return new CallSettings(name, surface, quiet, alert, newLineLength, newLinesPerSecond, callers, overdue);
    }

    /** Takes calls only from these addresses (a RUDICS gateway's, a modem server's). */
    public CallSettings withCallers(AddressRanges newCallers) {
        return new CallSettings(name, surface, quiet, alert, lineLength, linesPerSecond, newCallers, overdue);
    }

    /** Expects a call every {@code every} (null: the server learns it). */
    public CallSettings withOverdue(Duration every) {
        return new CallSettings(name, surface, quiet, alert, lineLength, linesPerSecond, callers, every);
    }
}
