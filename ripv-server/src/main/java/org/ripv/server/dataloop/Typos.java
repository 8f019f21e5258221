package org.ripv.server.dataloop;

/** Whether a word is a likely typo of another: at most one edit (insert, delete, change or swap of neighbours) apart. */
final class Typos {
    private Typos() {
    }

    static boolean near(String typed, String word) {
        if (typed.equals(word) || Math.abs(typed.length() - word.length()) > 1) {
            return typed.equals(word);
        }
        int[][] d = new int[typed.length() + 1][word.length() + 1];
        for (int i = 0; i <= typed.length(); i++) {
            for (int j = 0; j <= word.length(); j++) {
                if (i == 0 || j == 0) {
                    d[i][j] = i + j;
                    continue;
                }
                int change = typed.charAt(i - 1) == word.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + change);
                if (i > 1 && j > 1 && typed.charAt(i - 1) == word.charAt(j - 2) && typed.charAt(i - 2) == word.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[typed.length()][word.length()] <= 1;
    }
}
