/**
 * Checks on the text of a command before it goes anywhere near a vehicle: one line, no control
 * characters, bounded length ({@link org.ripv.commands.SingleLineCommand}), used by the server
 * before any permit rule is matched and again by the service before it writes to a link; and the
 * shape of a command table ({@link org.ripv.commands.WordTable}): each command named once by its
 * word, with its usage and help.
 */
package org.ripv.commands;
