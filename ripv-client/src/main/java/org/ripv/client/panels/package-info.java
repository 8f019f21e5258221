/**
 * The ServiceLayoutPanel and its quadrants: COM (command line and status labels), MAM, FIM, DAB (DatabasePanel) and DAV (ImagePanel).
 */
package org.ripv.client.panels;
