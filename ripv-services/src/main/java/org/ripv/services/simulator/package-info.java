/**
 * The glider simulator: a PicoDOS-like vehicle on a TCP port or a tty, or calling a
 * SerialPortServer's listen:// link like a Slocum glider (surface dialog with its GPS fix,
 * commands while up, hang-up to dive, call again), with a little file system, YMODEM send and
 * receive, ZMODEM through lrzsz ({@code Lrzsz}), and a GO command that
 * submerges it. With {@code --dialog gliderdos} it speaks enough of a Slocum's GliderDOS to
 * rehearse a surfacing ({@code SurfaceCountdown},
 * {@code GliderDos}); {@code IridiumLine}
 * makes a TCP call slow, late and dropped like a satellite call. docs/serial.md.
 */
package org.ripv.services.simulator;
