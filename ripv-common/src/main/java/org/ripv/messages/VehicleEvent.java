package org.ripv.messages;

/**
 * What happened on a vehicle link, as watchers, the transcript and notifications see it. The
 * service reports the call's life (SURFACED, DIVED, LINK_LOST), ALERTs and transfers; the server
 * adds what only it knows (locks, workflows).
 *
 * <p>The rules both sides apply to an event live here once: the call state it moves a vehicle to
 * (the server's {@code VehicleStates}, the clients' {@code SessionStates}), whether it is a
 * contact with the vehicle, and the groups pages and windows show alike.
 */
public enum VehicleEvent {
    /** A call began: carrier rose, a caller connected, or the surface dialog was seen. */
    SURFACED,
    /** The call ended normally: carrier fell, the caller hung up, or the vehicle went quiet. */
    DIVED,
    /** The link failed (I/O error, the device vanished, the service restarted mid-call). */
    LINK_LOST,
    /**
     * Something needs a pilot: a line of the vehicle's output matched the link's alert pattern, or
     * the server found trouble in a surfacing's call record (a new abort, a leak, the battery, …;
     * the text names the cause: docs/surfacings.md).
     */
    ALERT,
    TRANSFER_DONE,
    TRANSFER_FAILED,
    LOCK_TAKEN,
    LOCK_RELEASED,
    WORKFLOW_DONE,
    WORKFLOW_FAILED,
    /** A workflow reached its end, but steps marked {@code continue-on-error} failed on the way. */
    WORKFLOW_DONE_WITH_ERRORS,
    /**
     * A DatabaseServer keeps a Slocum binary file it cannot decode yet: its sensor list is in a
     * cache file ({@code CRC.cac}) the server does not hold. The text names the file and the CRC.
     */
    INGEST_WAITING,
    /** A file that waited for its sensor-list cache was ingested once the cache arrived. */
    INGEST_RELEASED,
    /**
     * A plan change (a behaviour file sent, a {@code put}) moved on: queued, sent, received, in
     * effect or not in effect (docs/plans.md). The text names the change and its new state.
     */
    PLAN_CHANGE,
    /**
     * The server's: a vehicle has not called within its expected interval plus a grace (set, or
     * learned from its recent calls), and again, saying how late, when it calls (docs/surfacings.md).
     */
    OVERDUE,
    /** A DatabaseServer refused a file (not a Slocum file, or broken): nothing of it stored; the text says why. */
    INGEST_REFUSED,
    /** A file whose bytes a DatabaseServer had stored already (fetched again): nothing added. */
    INGEST_REPEATED;

    /** The call state this event moves the vehicle to, or null when it leaves the state as it was. */
    public SessionState.State callState() {
        return switch (this) {
            case SURFACED -> SessionState.State.ON_CALL;
            case DIVED -> SessionState.State.DIVED;
            case LINK_LOST -> SessionState.State.LOST;
            default -> null;
        };
    }

    /** True for a new call: the vehicle's call count goes up by one. */
    public boolean startsCall() {
        return this == SURFACED;
    }

    /**
     * True when the vehicle itself was heard (its last contact moves): the call's life and what it
     * sent or said; not LINK_LOST (the link failed, the vehicle said nothing), nor what the server
     * or the database adds (locks, workflows, ingest).
     */
    public boolean fromVehicle() {
        return switch (this) {
            case SURFACED, DIVED, ALERT, TRANSFER_DONE, TRANSFER_FAILED -> true;
            default -> false;
        };
    }

    /** True for the end of a workflow run: WORKFLOW_DONE, WORKFLOW_DONE_WITH_ERRORS, WORKFLOW_FAILED. */
    public boolean endsWorkflow() {
        return this == WORKFLOW_DONE || this == WORKFLOW_DONE_WITH_ERRORS || this == WORKFLOW_FAILED;
    }
}
