/**
 * Exceptions a command handler throws to answer with a specific error code.
 */
package org.ripv.exceptions;
