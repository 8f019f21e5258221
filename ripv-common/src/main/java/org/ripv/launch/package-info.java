/**
 * Shared launcher plumbing: picocli command lines that report failures as {@code Error:} lines.
 */
package org.ripv.launch;
