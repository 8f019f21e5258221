/**
 * The interactive {@code ripv cli} on a terminal (JLine 3): the prompt, history, Tab completion and
 * Ctrl-C / Ctrl-D. Completion candidates come from {@link org.ripv.client.cli.shell.Completions}, a
 * model tested without a terminal; {@link org.ripv.client.cli.shell.ServerFacts} asks the server.
 */
package org.ripv.client.cli.shell;
