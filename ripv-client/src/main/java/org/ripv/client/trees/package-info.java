/**
 * The thesis's trees: ServiceTree (SEL), MailboxTree (MAM) and FileTree (FIM).
 */
package org.ripv.client.trees;
