/**
 * The server's upload and download directories: file-name rules, chunked uploads through temporary files and atomic moves.
 */
package org.ripv.server.files;
