package org.ripv.server.plans;

import java.util.ArrayList;
import java.util.List;

/**
 * A line diff of two versions of a behaviour file: each line of the result is {@code "  "} (in
 * both), {@code "- "} (only in the old) or {@code "+ "} (only in the new) and the line. The
 * longest common subsequence, so a moved waypoint reads as one line out and one in. Bounded:
 * past {@value #MAX_CELLS} cells of the table the files are said to be too long to compare.
 */
final class LineDiff {
    static final long MAX_CELLS = 4_000_000;

    private LineDiff() {
    }

    static List<String> diff(List<String> a, List<String> b) {
        // the common head and tail cost nothing; only the middle needs the table
        int head = 0;
        while (head < a.size() && head < b.size() && a.get(head).equals(b.get(head))) {
            head++;
        }
        int tail = 0;
        while (tail < a.size() - head && tail < b.size() - head && a.get(a.size() - 1 - tail).equals(b.get(b.size() - 1 - tail))) {
            tail++;
        }
        List<String> x = a.subList(head, a.size() - tail);
        List<String> y = b.subList(head, b.size() - tail);
        List<String> out = new ArrayList<>();
        a.subList(0, head).forEach(l -> out.add("  " + l));
        if ((long) (x.size() + 1) * (y.size() + 1) > MAX_CELLS) {
            out.add("- (" + x.size() + " lines)");
            out.add("+ (" + y.size() + " lines: too long to compare line by line)");
        } else {
            int[][] l = new int[x.size() + 1][y.size() + 1];
            for (int i = x.size() - 1; i >= 0; i--) {
                for (int j = y.size() - 1; j >= 0; j--) {
                    l[i][j] = x.get(i).equals(y.get(j)) ? l[i + 1][j + 1] + 1 : Math.max(l[i + 1][j], l[i][j + 1]);
                }
            }
            int i = 0;
            int j = 0;
            while (i < x.size() || j < y.size()) {
                if (i < x.size() && j < y.size() && x.get(i).equals(y.get(j))) {
                    out.add("  " + x.get(i++));
                    j++;
                } else if (i < x.size() && (j == y.size() || l[i + 1][j] >= l[i][j + 1])) {
                    out.add("- " + x.get(i++));
                } else {
                    out.add("+ " + y.get(j++));
                }
            }
        }
        a.subList(a.size() - tail, a.size()).forEach(line -> out.add("  " + line));
        return out;
    }
}
