/**
 * Locks the server holds: {@link org.ripv.server.lock.DataDirLock}, one server per data
 * directory (a second server, or a second demo, on it says which process holds it and stops
 * before touching its files); and {@link org.ripv.server.lock.OperatorLock}, an operator's or a
 * workflow's hold on a MailBox ({@code ?lock}).
 */
package org.ripv.server.lock;
