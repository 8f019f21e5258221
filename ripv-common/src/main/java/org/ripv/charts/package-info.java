/**
 * RIPV's one chart renderer ({@link org.ripv.charts.ChartRenderer}): a plot drawn by JFreeChart
 * the same way for the DataVisServer's built-in worker (JPEG), the client's interactive chart, and
 * the PNG and SVG (JFreeSVG) files the GUI and the CLI export. JFreeChart and JFreeSVG are optional
 * dependencies of ripv-common: the modules that draw (ripv-services, ripv-client) carry them.
 */
package org.ripv.charts;
