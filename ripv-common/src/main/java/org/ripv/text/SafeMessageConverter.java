package org.ripv.text;

import ch.qos.logback.classic.pattern.ClassicConverter;
import ch.qos.logback.classic.spi.ILoggingEvent;

/**
 * The log message with its non-printing characters escaped ({@link Printable#escape}): RIPV's
 * logback configurations print {@code %safemsg} rather than {@code %msg}, so a vehicle's line, a
 * workflow's notify text or a user's name in a log line cannot reach an operator's terminal as an
 * escape sequence.
 */
public final class SafeMessageConverter extends ClassicConverter {
    @Override
    public String convert(ILoggingEvent event) {
        return Printable.escape(event.getFormattedMessage());
    }
}
