package org.ripv.services.serial;

/** What a handler does with Data Carrier Detect. */
public enum CarrierMode {
    /** Send nothing while DCD is low and report the MailBox not available (modems, RF links). */
    REQUIRE,
    /** Ignore DCD (pseudo-terminals report every modem line low; TCP has none). */
    IGNORE
}
