/**
 * Every surfacing, understood (docs/surfacings.md): the server reads each vehicle's surface dialog
 * from the console entries it takes ({@link Surfacings}, with {@code org.ripv.surfacing}'s parser),
 * keeps a call record per surfacing in the state store ({@link CallRecord}), answers
 * {@code ?surfacings} ({@link SurfacingCommands}), raises ALERTs that name their cause against
 * per-vehicle thresholds with fleet defaults ({@link AlertRules}, {@link Alerts}), rate-limited per
 * vehicle and cause, and OVERDUE when a vehicle has not called within its expected interval
 * ({@link Overdue}). It gets the store, a way to publish events and its rules file; nothing else.
 */
package org.ripv.server.surfacing;
