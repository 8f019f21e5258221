/**
 * Files private to RIPV: directories created {@code 0700} and files {@code 0600}
 * ({@link org.ripv.files.PrivateFiles}), for the data directory, the database, work directories
 * and partial transfers.
 */
package org.ripv.files;
