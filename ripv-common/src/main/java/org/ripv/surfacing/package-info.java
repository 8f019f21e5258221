/**
 * A Slocum glider's surface dialog, understood: {@link SurfaceDialogParser} reads what a vehicle
 * prints as it streams (any chunking, lines joined, every line bounded) and hands a
 * {@link Surfacing} for each dialog — why it surfaced, its mission, its GPS and dead-reckoned
 * positions, the sensors of its surface list with their ages, its device error counts, its abort
 * history and the GliderDOS prompt — plus the dive countdown as it ticks.
 *
 * <p>Both sides use it: the SerialPortServer to tell a call dropped mid-dialog from one that ended,
 * the server to keep a call record per surfacing and raise alerts (docs/surfacings.md). Pure Java,
 * no I/O; text it does not know is kept (bounded), never an error.
 */
package org.ripv.surfacing;
