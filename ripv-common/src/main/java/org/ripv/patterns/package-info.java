/**
 * Patterns people give RIPV ({@code wait-for}, {@code expect=}, {@code fail=}, {@code surface=},
 * {@code alert=}, searches): compiled with RE2/J, so matching takes time linear in the text
 * whatever the pattern — a pattern like {@code ((.*)*)*X} cannot stall the thread that matches it
 * (issue 23, item 3). Java's own {@code java.util.regex} backtracks and is kept for RIPV's own
 * fixed patterns only.
 */
package org.ripv.patterns;
