/**
 * Enlarging, maximising and restoring the quadrants of a service tab: {@link
 * org.ripv.client.layout.QuadrantState} decides (plain code, tested headless), {@link
 * org.ripv.client.layout.Quadrants} moves the split panes' dividers and components.
 */
package org.ripv.client.layout;
