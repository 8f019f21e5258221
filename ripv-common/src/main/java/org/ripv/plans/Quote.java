package org.ripv.plans;

/** How text from a file is quoted in a problem: cut, so a hostile line never makes a hostile message. */
final class Quote {
    private Quote() {
    }

    static String cut(String s) {
        return s.length() <= 40 ? s : s.substring(0, 40) + "…";
    }
}
