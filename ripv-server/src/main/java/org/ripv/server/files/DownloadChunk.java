package org.ripv.server.files;

/**
 * Part of a downloaded file, as {@code ?download NAME OFFSET LENGTH} reads it.
 *
 * @param total the whole file's size in bytes
 * @param data  the bytes from the offset asked for (fewer at the end of the file)
 */
public record DownloadChunk(long total, byte[] data) {}
