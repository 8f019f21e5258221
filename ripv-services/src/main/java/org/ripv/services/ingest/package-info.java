/**
 * Slocum glider data into the database: {@link org.ripv.services.ingest.DbaReader} reads DBA
 * files ({@code dbd2asc} output, merged {@code .mrg}) strictly and streaming, converting
 * positions from DDMM.MMMM ({@link org.ripv.services.ingest.Degrees}); {@link
 * org.ripv.services.ingest.DbaIngest} stores one file in the narrow schema of
 * {@code sql/slocumDB.sql} in one transaction, once per SHA-256. The DatabaseServer's
 * {@code ingest NAME...} command drives it (docs/database.md).
 *
 * <p>Threads: none of its own; both classes run on the caller's thread (a DatabaseServer
 * MailBox's inbox assistant).
 */
package org.ripv.services.ingest;
