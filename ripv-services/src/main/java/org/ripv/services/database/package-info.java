/**
 * The DatabaseServer (SID 666666): SQL to embedded Apache Derby or any JDBC database, one
 * MailBox per database connection (thesis 4.1.4.2, Appendix C; {@code docs/database.md}).
 *
 * <ul>
 *   <li>{@link org.ripv.services.database.DatabaseServer} — the service; opens one MailBox
 *       per {@link org.ripv.services.database.DatabaseTarget}.</li>
 *   <li>{@link org.ripv.services.database.DatabaseHandler} — runs one MailBox's SQL: queries
 *       to {@code TableResult}, updates to {@code UpdateCount}, database errors with their
 *       SQLState; owner and read-only reader connections.</li>
 *   <li>{@link org.ripv.services.database.ResultPages} — a query's rows leave in pages, each once
 *       the reader has room for it, so no result is ever held whole (issue 38).</li>
 *   <li>{@link org.ripv.services.database.EmbeddedDatabase} — the default database: created,
 *       seeded and secured (NATIVE users, SQL authorization, read-only reader) on first start.</li>
 *   <li>{@link org.ripv.services.database.SqlScript} — splits and runs the scripts of {@code sql/}.</li>
 *   <li>{@link org.ripv.services.database.DatabaseServerCommand} — the launcher.</li>
 * </ul>
 *
 * <p>Threads: each MailBox's commands run one at a time on its inbox assistant thread
 * ({@code mailbox-<DatabaseServer>::<host>TTY1-inbox}), which alone touches that MailBox's JDBC
 * connections; {@code ?status} reads a volatile availability snapshot from the RMI threads.
 * The service starts no threads of its own.
 */
package org.ripv.services.database;
