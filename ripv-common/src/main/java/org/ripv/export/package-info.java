/**
 * Query results and chart data as CSV (RFC 4180) and JSON files, and a chart as an SVG picture
 * drawn from its data ({@link org.ripv.export.SvgChart}), the same for the CLI's
 * {@code export csv|json|svg FILE} and the GUI's export buttons (JSON through {@link org.ripv.json.Json}).
 */
package org.ripv.export;
