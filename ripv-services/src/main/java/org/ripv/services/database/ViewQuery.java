package org.ripv.services.database;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Pattern;

/**
 * What a view user ({@value #ROLE}) may run: one {@code SELECT} from one of the data views,
 * nothing else (issue 33 item 6). A permit rule is a glob over the command's text, and
 * {@code SELECT * FROM positions ORDER BY*} let a subquery in ORDER BY read any table a bit at a
 * time and a cross join of system tables run for seconds. So the statement is read here: no
 * parentheses (so no subquery and no function call), no comments, one {@code FROM} naming one view
 * (no second table, no join, no union), then only {@code WHERE}, {@code ORDER BY},
 * {@code OFFSET} and {@code FETCH}. String literals may hold anything; {@code CAST('2016-01-13
 * 17:00:00' AS TIMESTAMP)}, a time as the server's plots write it, is a literal too. Such a statement reads one
 * view in linear time; it also runs under {@link #TIMEOUT_SECONDS}.
 */
public final class ViewQuery {
    /** The permit-file role of users who may read the data views only. */
    public static final String ROLE = "db-views";
    /** The views ({@code sql/slocumDB.sql}) a view user may read. */
    public static final Set<String> VIEWS = Set.of("POSITIONS", "LATEST", "DIVES", "DEPTHS");
    /** A view user's statement is cancelled after this (or the service's own limit, when shorter). */
    public static final int TIMEOUT_SECONDS = 5;

    private static final Set<String> NEVER = Set.of("SELECT", "FROM", "JOIN", "UNION", "INTERSECT", "EXCEPT", "TABLE", "VALUES",
            "INTO", "FOR", "WITH", "CALL", "LATERAL");
    private static final Set<String> AFTER_VIEW = Set.of("WHERE", "ORDER", "OFFSET", "FETCH");

    private ViewQuery() {}

    /** True when the roles make the user a view user: {@value #ROLE} and no role that may write. */
    public static boolean appliesTo(List<String> roles) {
        return roles.contains(ROLE) && DatabaseHandler.readsOnly(roles);
    }

    /** A time literal, as the plots the server runs for the user write it: the one parenthesis allowed. */
    private static final Pattern TIME_LITERAL = Pattern.compile(
            "(?i)CAST\\s*\\(\\s*'[0-9 :.T\\-]{1,40}'\\s+AS\\s+(TIMESTAMP|DATE|TIME)\\s*\\)");

    /** Returns null when {@code sql} is one SELECT from one view, else why not (quoting it). */
    public static String refusal(String sql) {
        List<String> words;
        try {
            words = words(TIME_LITERAL.matcher(sql).replaceAll("'t'"));
        } catch (IllegalArgumentException e) {
            return why(sql, e.getMessage());
        }
        if (words.isEmpty() || !words.get(0).equals("SELECT")) {
            return why(sql, "it is not a SELECT");
        }
        int from = words.indexOf("FROM");
        if (from < 0 || from + 1 >= words.size()) {
            return why(sql, "it names no view after FROM");
        }
        for (int i = 1; i < words.size(); i++) {
            if (i != from && NEVER.contains(words.get(i))) {
                return why(sql, "it holds " + words.get(i) + " (one SELECT from one view only)");
            }
        }
        String view = words.get(from + 1);
        if (view.startsWith("APP.")) {
            view = view.substring(4);
        }
        if (!VIEWS.contains(view)) {
            return why(sql, "'" + words.get(from + 1) + "' is not one of the views " + new TreeSet<>(VIEWS));
        }
        if (from + 2 < words.size() && !AFTER_VIEW.contains(words.get(from + 2))) {
            return why(sql, "only WHERE, ORDER BY, OFFSET or FETCH may follow the view, not '" + words.get(from + 2) + "'");
        }
        return null;
    }

    private static String why(String sql, String reason) {
        String shown = sql.length() > 120 ? sql.substring(0, 120) + "…" : sql;
        return "view users (role " + ROLE + ") may run one SELECT from one of the views " + new TreeSet<>(VIEWS)
                + " with WHERE, ORDER BY, OFFSET and FETCH and no parentheses; '" + shown + "' is refused: " + reason;
    }

    /**
     * The statement's words, upper-cased, string literals dropped, {@code schema.name} and quoted
     * identifiers as one word; parentheses and comments refused.
     */
    static List<String> words(String sql) {
        List<String> out = new ArrayList<>();
        int i = 0;
        int n = sql.length();
        while (i < n) {
            char c = sql.charAt(i);
            if (c == '\'') {
                int end = i + 1;
                while (true) {
                    if (end >= n) {
                        throw new IllegalArgumentException("a string is not closed");
                    }
                    if (sql.charAt(end) == '\'') {
                        if (end + 1 < n && sql.charAt(end + 1) == '\'') {
                            end += 2;
                            continue;
                        }
                        break;
                    }
                    end++;
                }
                out.add("'");
                i = end + 1;
            } else if (c == '(' || c == ')' || c == '{' || c == '}' || c == '[' || c == ']') {
                throw new IllegalArgumentException("it holds '" + c + "' (no subqueries or functions)");
            } else if (c == '-' && i + 1 < n && sql.charAt(i + 1) == '-' || c == '/' && i + 1 < n && sql.charAt(i + 1) == '*') {
                throw new IllegalArgumentException("it holds a comment");
            } else if (c == ';') {
                throw new IllegalArgumentException("it holds ';'");
            } else if (Character.isWhitespace(c)) {
                i++;
            } else if (c == '"' || Character.isLetterOrDigit(c) || c == '_') {
                StringBuilder w = new StringBuilder();
                while (i < n && (sql.charAt(i) == '"' || sql.charAt(i) == '.' || Character.isLetterOrDigit(sql.charAt(i))
                        || sql.charAt(i) == '_')) {
                    if (sql.charAt(i) == '"') {
                        int end = sql.indexOf('"', i + 1);
                        if (end < 0) {
                            throw new IllegalArgumentException("a quoted name is not closed");
                        }
                        w.append(sql, i + 1, end); // a quoted name keeps its case: "positions" is not the view POSITIONS
                        i = end + 1;
                    } else {
                        w.append(Character.toUpperCase(sql.charAt(i)));
                        i++;
                    }
                }
                out.add(w.toString().toUpperCase(Locale.ROOT).equals(w.toString()) ? w.toString() : "\"" + w + "\"");
            } else {
                out.add(String.valueOf(c));
                i++;
            }
        }
        return out;
    }
}
