package org.ripv.server.routing;

import org.ripv.messages.OutgoingServerMessage;

/**
 * One check a request to a service passes before it is forwarded (as OkHttp's interceptors or
 * Jetty's handlers): each is small, named for what it checks, and testable alone. What a request
 * has shown so far lives in {@link Admitting}, not in a step, so a step that needs collaborators
 * is a record of them.
 */
@FunctionalInterface
public interface AdmissionStep {
    /**
     * @return {@link Verdict#PASS} for the next step, {@link Verdict#TAKEN} when this step has
     *         answered the request itself, or {@link Verdict#refuse} with the reply that refuses it
     */
    Verdict check(Admitting request);

    /** What a step decided. */
    record Verdict(OutgoingServerMessage refusal, boolean taken) {
        public static final Verdict PASS = new Verdict(null, false);
        public static final Verdict TAKEN = new Verdict(null, true);

        public static Verdict refuse(OutgoingServerMessage refusal) {
            return new Verdict(refusal, false);
        }

        public boolean passed() {
            return refusal == null && !taken;
        }
    }
}
