/**
 * Query results and chart data as CSV (RFC 4180) and JSON files, the same for the CLI's
 * {@code export csv|json FILE} and the GUI's export buttons (JSON through {@link org.ripv.json.Json}).
 * Charts as pictures (PNG, SVG) are drawn by {@link org.ripv.charts.ChartRenderer}.
 */
package org.ripv.export;
