/**
 * The one JSON RIPV writes and reads, through Jackson: the CLI's {@code --json} lines, export
 * files, the server's transcripts, subscriptions and webhooks ({@link org.ripv.json.Json}).
 */
package org.ripv.json;
