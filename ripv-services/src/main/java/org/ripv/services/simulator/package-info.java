/**
 * The glider simulator: a PicoDOS-like vehicle on a TCP port or a tty, or calling a
 * SerialPortServer's listen:// link like a Slocum glider (surface dialog with its GPS fix,
 * commands while up, hang-up to dive, call again), with a little file system, YMODEM send and
 * receive, and a GO command that submerges it.
 */
package org.ripv.services.simulator;
