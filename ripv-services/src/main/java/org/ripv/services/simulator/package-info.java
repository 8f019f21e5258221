/**
 * The glider simulator: a PicoDOS-like vehicle on a TCP port or a tty, with a little file
 * system, YMODEM send and receive, and a GO command that submerges it.
 */
package org.ripv.services.simulator;
