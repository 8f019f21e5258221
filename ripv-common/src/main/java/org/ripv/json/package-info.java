/** The one JSON writer RIPV shares: the CLI's {@code --json} lines, export files, transcripts and webhooks. */
package org.ripv.json;
