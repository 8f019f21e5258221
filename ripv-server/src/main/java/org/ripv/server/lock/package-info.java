/**
 * One server per data directory: {@link org.ripv.server.lock.DataDirLock} is held by the
 * RIPVServer process that uses a directory, so a second server (or a second demo) on it says
 * which process holds it and stops before touching its files.
 */
package org.ripv.server.lock;
