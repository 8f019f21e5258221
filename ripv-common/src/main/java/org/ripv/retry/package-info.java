/** Trying again: {@link org.ripv.retry.Backoff}, the growing wait between tries that every retry loop in RIPV shares. */
package org.ripv.retry;
