/**
 * The client's state and behaviour, testable without a display: {@link org.ripv.client.managers.GuiManager} implements {@link org.ripv.client.managers.GuiInterface} and dispatches every reply by its Footer's SID or FID into the model; the session (log-in, reconnect), requests, transfers, reply dispatch, the MailBox targets and the console routing are its collaborators. Model changes happen on the event thread; network and file work never do.
 */
package org.ripv.client.managers;
