/**
 * Checks on the text of a command before it goes anywhere near a vehicle: one line, no control
 * characters, bounded length ({@link org.ripv.commands.SingleLineCommand}), used by the server
 * before any permit rule is matched and again by the service before it writes to a link.
 */
package org.ripv.commands;
