package org.ripv.messages;

/**
 * The six-digit identifiers of Appendix B. A reply's {@link Footer#serviceId()} carries the SID of
 * the service that produced it or the FID of the server command that answered it; clients
 * dispatch on it. New server commands take new FIDs here and in {@code docs/protocol.md}.
 */
public final class Ids {

    // Service IDs (SID), Appendix B.
    public static final String SID_DATABASE = "666666";
    public static final String SID_SERIAL = "888888";
    public static final String SID_DATAVIS = "999999";

    // Functionality IDs (FID) of the thesis's server commands, Appendix B.
    public static final String FID_DLDIR = "444444";
    public static final String FID_ULDIR = "444445";
    public static final String FID_DLFILES = "444454";
    public static final String FID_ULFILES = "444455";
    public static final String FID_MAILBOXES = "555555";
    public static final String FID_STATUS = "555666";
    public static final String FID_SERVICES = "777777";

    // FIDs added by this implementation (docs/protocol.md).
    public static final String FID_LOGIN = "111111";
    public static final String FID_LOGOUT = "111112";
    public static final String FID_WHOAMI = "111113";
    public static final String FID_HELP = "111110";
    public static final String FID_PING = "111115";
    public static final String FID_UPLOAD = "444460";
    public static final String FID_DOWNLOAD = "444470";
    public static final String FID_LOCK = "555667";
    public static final String FID_UNLOCK = "555668";
    // Log-in security (issue 10 part A, FIDs 111120-111139).
    /** {@code ?logins}: users and addresses with failed log-ins, and their blocks. */
    public static final String FID_LOGINS = "111120";
    /** {@code ?unlock-login USER|ADDRESS}: lifts a log-in block or lock. */
    public static final String FID_UNLOCK_LOGIN = "111121";
    // The state store (issue 15, range 777720-777739).
    /** {@code ?audit [--last N] [--since ISO-TIME]}: the audit trail, from the server's state store. */
    public static final String FID_AUDIT = "777720";
    // Store files (issue 10 part B), range 444480-444499.
    /** {@code ?delete NAME}: removes a file from the upload or download store. */
    public static final String FID_DELETE = "444480";
    // The live console, vehicle state, transcript and notifications (docs/sessions.md).
    public static final String FID_WATCH = "555700";
    public static final String FID_UNWATCH = "555701";
    public static final String FID_HISTORY = "555702";
    public static final String FID_NOTIFY = "555703";
    /** {@code ?surfacings MAILBOX}: a vehicle's call records (docs/surfacings.md). */
    public static final String FID_SURFACINGS = "555704";
    /** Console entries pushed to watchers (message id 0, status PROGRESS, a {@link ConsoleBatch}). */
    public static final String FID_CONSOLE = "555790";
    // Workflows and cancel (docs/workflows.md): 555800-555899.
    public static final String FID_QUEUE = "555800";
    public static final String FID_RECEIPTS = "555801";
    public static final String FID_CANCEL = "555802";
    // Plans and their changes (docs/plans.md): 555810-555819.
    /** {@code ?plan MAILBOX check|send|set|forecast|save|history|current ...}: behaviour files checked, sent, kept, parameters set. */
    public static final String FID_PLAN = "555810";
    /** {@code ?changes [MAILBOX]}: each change sent to a vehicle and how far it got. */
    public static final String FID_CHANGES = "555811";
    /** {@code ?key MAILBOX KEY}: one control key to a vehicle (docs/serial.md#control-keys). */
    public static final String FID_KEY = "555720";
    /** {@code ?dac MAILBOX}: a DatabaseServer's IOOS Glider DAC deliveries (docs/dac.md). */
    public static final String FID_DAC = "555820";
    /** Replies to a message the server could not attribute to any command or service. */
    public static final String FID_NONE = "000000";

    private Ids() {}

    /** True when {@code id} is six ASCII digits. */
    public static boolean isValid(String id) {
        if (id == null || id.length() != 6) {
            return false;
        }
        for (int i = 0; i < 6; i++) {
            char c = id.charAt(i);
            if (c < '0' || c > '9') {
                return false;
            }
        }
        return true;
    }

    /** Returns {@code id} or throws when it is not six digits. */
    public static String require(String id) {
        if (!isValid(id)) {
            throw new IllegalArgumentException("an id must be six digits, got '" + id + "'");
        }
        return id;
    }
}
