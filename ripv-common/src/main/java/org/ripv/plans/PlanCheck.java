package org.ripv.plans;

import java.util.List;

/** The outcome of reading a behaviour file: the file when it passed, else its problems (never both). */
public record PlanCheck(BehaviorFile file, List<PlanProblem> problems) {
    public PlanCheck {
        problems = List.copyOf(problems);
        if ((file == null) == problems.isEmpty()) {
            throw new IllegalArgumentException("a check has a file or problems, not both");
        }
    }

    public boolean ok() {
        return file != null;
    }

    /** The problems, one {@code FILE:LINE: reason} a line. */
    public String problemText() {
        StringBuilder b = new StringBuilder();
        for (PlanProblem p : problems) {
            b.append(b.length() == 0 ? "" : "\n").append(p);
        }
        return b.toString();
    }
}
