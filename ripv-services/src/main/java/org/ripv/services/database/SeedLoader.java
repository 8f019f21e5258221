package org.ripv.services.database;

import java.math.BigDecimal;
import java.sql.Connection;
import java.sql.ParameterMetaData;
import java.sql.PreparedStatement;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Runs a seed script such as {@code sample-data.sql} fast: each multi-row
 * {@code INSERT INTO t (cols) VALUES (...), (...)} becomes one prepared statement per table and
 * a JDBC batch of its rows, instead of one huge statement that Derby must compile (the
 * compilation, not the writing, took most of the 20-odd seconds of a first start). Values must
 * be literals — numbers, {@code '...'} strings (which Derby converts to the column's type, dates
 * and times included) and {@code NULL}; any other statement runs as it is.
 */
final class SeedLoader {
    private static final Pattern INSERT = Pattern.compile(
            "(?is)INSERT\\s+INTO\\s+(\\w+)\\s*\\(([^)]*)\\)\\s*VALUES\\s*(\\(.*\\))\\s*");
    private static final Pattern NUMBER = Pattern.compile("[-+]?(\\d+\\.?\\d*|\\.\\d+)([eE][-+]?\\d+)?");

    private SeedLoader() {}

    /** Runs every statement of the script on the connection, batching its INSERTs. Returns the rows inserted. */
    static long run(Connection c, String script, String name) throws SQLException {
        long rows = 0;
        List<String> statements = SqlScript.split(script);
        Map<String, PreparedStatement> prepared = new HashMap<>();
        try (Statement plain = c.createStatement()) {
            for (int i = 0; i < statements.size(); i++) {
                String sql = statements.get(i);
                Matcher m = INSERT.matcher(sql);
                try {
                    if (!m.matches()) {
                        plain.execute(sql);
                        continue;
                    }
                    String head = "INSERT INTO " + m.group(1) + " (" + m.group(2) + ")";
                    int columns = m.group(2).split(",").length;
                    PreparedStatement ps = prepared.get(head);
                    if (ps == null) {
                        ps = c.prepareStatement(head + " VALUES (" + "?, ".repeat(columns - 1) + "?)");
                        prepared.put(head, ps);
                    }
                    ParameterMetaData meta = ps.getParameterMetaData();
                    for (List<String> tuple : tuples(m.group(3))) {
                        if (tuple.size() != columns) {
                            throw new SQLException("a row of " + tuple.size() + " values for " + columns + " columns");
                        }
                        for (int k = 0; k < columns; k++) {
                            bind(ps, meta, k + 1, tuple.get(k));
                        }
                        ps.addBatch();
                        rows++;
                    }
                    ps.executeBatch();
                } catch (SQLException | IllegalArgumentException e) {
                    throw new SQLException(name + ", statement " + (i + 1) + " of " + statements.size() + " ("
                            + SqlScript.abbreviate(sql) + "): " + e.getMessage(),
                            e instanceof SQLException s ? s.getSQLState() : "42000", e);
                }
            }
        } finally {
            for (PreparedStatement ps : prepared.values()) {
                ps.close();
            }
        }
        return rows;
    }

    private static void bind(PreparedStatement ps, ParameterMetaData meta, int index, String literal) throws SQLException {
        if (literal.equalsIgnoreCase("NULL")) {
            ps.setNull(index, meta.getParameterType(index));
        } else if (literal.startsWith("'")) {
            ps.setString(index, literal.substring(1, literal.length() - 1).replace("''", "'"));
        } else if (NUMBER.matcher(literal).matches()) {
            ps.setBigDecimal(index, new BigDecimal(literal));
        } else {
            throw new IllegalArgumentException("not a literal: " + literal);
        }
    }

    /** Splits {@code (a, 'b, c'), (NULL, 2)} into rows of literal texts. */
    static List<List<String>> tuples(String values) {
        List<List<String>> rows = new ArrayList<>();
        List<String> row = null;
        StringBuilder v = new StringBuilder();
        int n = values.length();
        for (int i = 0; i < n; i++) {
            char ch = values.charAt(i);
            if (ch == '\'') {
                int end = i + 1;
                while (true) {
                    end = values.indexOf('\'', end);
                    if (end < 0) {
                        throw new IllegalArgumentException("unterminated string literal");
                    }
                    if (end + 1 < n && values.charAt(end + 1) == '\'') {
                        end += 2;
                        continue;
                    }
                    break;
                }
                v.append(values, i, end + 1);
                i = end;
            } else if (ch == '(' && row == null) {
                row = new ArrayList<>();
                v.setLength(0);
            } else if (ch == ',' && row != null) {
                row.add(v.toString().strip());
                v.setLength(0);
            } else if (ch == ')' && row != null) {
                row.add(v.toString().strip());
                rows.add(row);
                row = null;
                v.setLength(0);
            } else if (row != null) {
                v.append(ch);
            } else if (ch != ',' && !Character.isWhitespace(ch)) {
                throw new IllegalArgumentException("unexpected '" + ch + "' between rows");
            }
        }
        if (row != null) {
            throw new IllegalArgumentException("unterminated row");
        }
        return rows;
    }
}
