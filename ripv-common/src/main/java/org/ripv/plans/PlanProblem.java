package org.ripv.plans;

/** One reason a behaviour file is refused, where it is: printed {@code FILE:LINE: reason} as compilers do. */
public record PlanProblem(String file, int line, String reason) {
    @Override
    public String toString() {
        return file + ":" + line + ": " + reason;
    }
}
