/**
 * The SerialPortServer (SID 888888): one SerialPortHandler and MailBox per serial port and per
 * named link (device path, pseudo-terminal, tcp://host:port, or listen://[ADDR:]PORT where the
 * vehicle calls in), plain commands to a vehicle's shell (cancelled with the link's interrupt),
 * YMODEM transfers (with a clean line after each: {@code LineSync}), carrier handling,
 * reconnection of links that fail, and the live console: one reader per link publishes
 * everything the vehicle prints, the commands sent, transfers and the call's events (SURFACED
 * with the GPS fix, DIVED, LINK_LOST, ALERT) through {@code RIPVService.publish}.
 */
package org.ripv.services.serial;
