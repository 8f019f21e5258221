/**
 * {@code ripv slocum}: Slocum glider files on the command line, without Teledyne's tools —
 * {@code decode} prints what {@code dbd2asc} prints for binary files (plain or LZ4-compressed),
 * {@code --merge} what {@code dba_merge} makes of a flight and science pair (docs/slocum.md).
 * The decoding itself is {@link org.ripv.services.ingest.SlocumBinaryReader}'s.
 */
package org.ripv.services.slocum;
