/**
 * RIPV's own ZMODEM over any {@code ByteLink}: hex, 16- and 32-bit binary headers, CRC-32 data
 * subpackets, streaming with {@code ZRPOS} error recovery, and crash recovery (a file a dropped
 * call cut short is kept as a marked partial file and continued from its length on the next
 * call, unless the vehicle's copy changed). It interoperates with lrzsz's {@code sz}/{@code rz}.
 */
package org.ripv.services.serial.zmodem;
