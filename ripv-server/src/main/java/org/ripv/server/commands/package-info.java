/**
 * The server's own {@code ?} commands (Appendix B, docs/protocol.md): one
 * {@link org.ripv.server.commands.CommandTable} names each command once (word, FID, usage, help,
 * whether the permit file must allow it, where it runs, its handler); routing, {@code ?help} and
 * the clients' completion all read it. docs/extending.md says how to add one.
 */
package org.ripv.server.commands;
