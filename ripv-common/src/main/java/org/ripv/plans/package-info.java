/**
 * Slocum glider behaviour files ({@code .ma}: {@code goto_l10.ma}, {@code surfac06.ma},
 * {@code yo10.ma}) read as the glider reads them, and checked before one is sent: the
 * {@code behavior_name=} line, the {@code <start:b_arg>} block and, for {@code goto_list}, the
 * {@code <start:waypoints>} list of {@code LON LAT} in DDMM.mmmm. A file is either a
 * {@link org.ripv.plans.BehaviorFile} or a list of {@link org.ripv.plans.PlanProblem}s, each
 * {@code FILE:LINE: reason}.
 *
 * <p>Files come from anywhere, so {@link org.ripv.plans.BehaviorFileReader} treats every byte as
 * hostile: a line, the file and the waypoint list are bounded ({@link org.ripv.plans.PlanLimits}),
 * control bytes and non-ASCII outside comments are refused with their line. Pure Java, shared
 * by the offline {@code ripv plan check} ({@link org.ripv.plans.PlanMain}) and the server's
 * {@code ?plan}. The change follower's input, {@link org.ripv.plans.SurfacingFacts}, is also
 * here so that any reader of a surface dialog can feed it.
 */
package org.ripv.plans;
