/**
 * The RIPV Post Office's TaskManager (thesis figure 5.3) and the admission of a request to a
 * service: {@link org.ripv.server.routing.Admission} passes it through nine small
 * {@link org.ripv.server.routing.AdmissionStep}s — mailbox chosen, service registered, one line,
 * user known, permit allows, lock free, plot takeover, to-vehicle folder rule, attachment — and
 * forwards it, or the first step that refuses it says why. Each step is testable alone.
 */
package org.ripv.server.routing;
