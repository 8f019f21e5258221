/**
 * Plans on the server (issue 36, docs/plans.md): {@code ?plan MAILBOX check|send|set} checks a
 * Slocum behaviour file ({@link org.ripv.plans}), stages it in the vehicle's to-vehicle folder
 * or queues a {@code put} as a workflow; {@code ?plan MAILBOX save|history} keeps every saved
 * version with its diff against the last sent ({@link org.ripv.server.plans.PlanVersions});
 * {@code ?plan MAILBOX current} tells the goto list the glider runs; {@code ?changes} follows each
 * change from queued to sent, received and in effect (or not in effect, an ALERT; or cancelled,
 * its staged file gone) by what the vehicle's console shows.
 *
 * <p>It sees the server only through {@link org.ripv.server.plans.PlanHost}. The follower's
 * input per surfacing is {@link org.ripv.plans.SurfacingFacts}, made from the dialog the
 * surfacing parser read ({@code org.ripv.server.surfacing.Surfacings} hands each to
 * {@link org.ripv.server.plans.Plans#surfacing(String, long, org.ripv.surfacing.Surfacing)}).
 */
package org.ripv.server.plans;
