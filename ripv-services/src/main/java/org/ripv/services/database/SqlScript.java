package org.ripv.services.database;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.sql.Connection;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;

/**
 * An SQL script such as {@code vehicleDB.sql}, split into statements that JDBC can run one by
 * one. JDBC drivers take one statement per call and Derby rejects a trailing {@code ;}, so the
 * script is cut at each {@code ;} that is outside a {@code '...'} literal, a {@code "..."}
 * identifier, a {@code --} comment and a {@code /* *}{@code /} comment. Comments are dropped.
 * That is all the dialect the RIPV scripts use; procedural blocks with nested {@code ;} are
 * not supported.
 */
public final class SqlScript {
    /** Where the scripts of {@code sql/} are on the class path. */
    public static final String RESOURCE_DIR = "/sql/";

    private SqlScript() {}

    /** Splits a script into its statements, without comments and without the {@code ;}. */
    public static List<String> split(String script) {
        List<String> statements = new ArrayList<>();
        StringBuilder current = new StringBuilder();
        int n = script.length();
        int i = 0;
        while (i < n) {
            char c = script.charAt(i);
            if (c == '\'' || c == '"') {
                int end = script.indexOf(c, i + 1);
                // a doubled quote inside a literal ('St. David''s') is two adjacent literals to this scan
                if (end < 0) {
                    throw new IllegalArgumentException("unterminated " + (c == '\'' ? "string literal" : "quoted identifier")
                            + " starting at line " + line(script, i));
                }
                current.append(script, i, end + 1);
                i = end + 1;
            } else if (c == '-' && i + 1 < n && script.charAt(i + 1) == '-') {
                int end = script.indexOf('\n', i);
                i = end < 0 ? n : end;
            } else if (c == '/' && i + 1 < n && script.charAt(i + 1) == '*') {
                int end = script.indexOf("*/", i + 2);
                if (end < 0) {
                    throw new IllegalArgumentException("unterminated /* comment starting at line " + line(script, i));
                }
                i = end + 2;
                current.append(' ');
            } else if (c == ';') {
                add(statements, current);
                i++;
            } else {
                current.append(c);
                i++;
            }
        }
        add(statements, current);
        return statements;
    }

    private static void add(List<String> statements, StringBuilder current) {
        String s = current.toString().strip();
        if (!s.isEmpty()) {
            statements.add(s);
        }
        current.setLength(0);
    }

    private static int line(String s, int index) {
        int line = 1;
        for (int i = 0; i < index; i++) {
            if (s.charAt(i) == '\n') {
                line++;
            }
        }
        return line;
    }

    /** Reads a script shipped in the jar, e.g. {@code resource("vehicleDB.sql")}. */
    public static String resource(String name) throws IOException {
        try (InputStream in = SqlScript.class.getResourceAsStream(RESOURCE_DIR + name)) {
            if (in == null) {
                throw new IOException("SQL script " + RESOURCE_DIR + name + " is not on the class path"
                        + " (ripv-services copies ../sql into the jar; was it built from a full checkout?)");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    /**
     * Runs every statement of a script on a connection, in order. A failing statement stops the
     * script with an exception that names it.
     *
     * @return the number of statements run
     */
    public static int run(Connection connection, String script, String scriptName) throws SQLException {
        List<String> statements = split(script);
        try (Statement st = connection.createStatement()) {
            for (int i = 0; i < statements.size(); i++) {
                String sql = statements.get(i);
                try {
                    st.execute(sql);
                } catch (SQLException e) {
                    throw new SQLException(scriptName + ", statement " + (i + 1) + " of " + statements.size() + " ("
                            + abbreviate(sql) + "): " + e.getMessage(), e.getSQLState(), e.getErrorCode(), e);
                }
            }
        }
        return statements.size();
    }

    static String abbreviate(String sql) {
        String one = sql.replaceAll("\\s+", " ");
        return one.length() <= 100 ? one : one.substring(0, 97) + "...";
    }
}
