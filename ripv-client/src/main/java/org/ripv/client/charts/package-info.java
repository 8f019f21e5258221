/**
 * Interactive plots in the DAV panel: a DataVisServer reply's {@link org.ripv.messages.ChartData}
 * drawn by JFreeChart's {@code ChartPanel} (zoom, pan, the value under the cursor, PNG and SVG),
 * the JPEG when a worker sent no data (Octave, MATLAB). {@link org.ripv.client.charts.Charts} and
 * {@link org.ripv.client.charts.Readout} are plain code, testable headless; {@link
 * org.ripv.client.charts.PlotPanel} is the thin Swing view.
 */
package org.ripv.client.charts;
