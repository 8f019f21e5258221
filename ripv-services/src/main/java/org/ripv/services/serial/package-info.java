/**
 * The SerialPortServer (SID 888888): one SerialPortHandler and MailBox per serial port and per
 * named link (device path, pseudo-terminal, or tcp://host:port), plain commands to a vehicle's
 * shell, YMODEM transfers, carrier handling, and reconnection of links that fail.
 */
package org.ripv.services.serial;
