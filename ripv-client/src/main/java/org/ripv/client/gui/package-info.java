/**
 * The Swing RIPVClient (thesis 4.1.2–4.1.3): the main window, the log-in dialog and the {@code client} launcher. Thin: it renders what {@link org.ripv.client.managers.GuiManager} keeps in the model and forwards the operator's actions.
 */
package org.ripv.client.gui;
