/**
 * RIPV's own YMODEM (batch, CRC16CCITT, 128- and 1024-byte blocks) over any {@code ByteLink};
 * it interoperates with lrzsz's {@code sb}/{@code rb --ymodem}.
 */
package org.ripv.services.serial.ymodem;
