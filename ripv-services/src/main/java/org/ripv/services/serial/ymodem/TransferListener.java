package org.ripv.services.serial.ymodem;

/** Hears how a transfer goes; called on the transferring thread. */
public interface TransferListener {
    TransferListener NONE = new TransferListener() { };

    default void started(FileHeader file) {
    }

    /** {@code done} bytes of {@code file} have been acknowledged (sender) or accepted (receiver). */
    default void progress(FileHeader file, long done) {
    }

    default void finished(FileHeader file) {
    }

    /**
     * The file continues from byte {@code offset} a dropped call left (ZMODEM crash recovery):
     * the bytes before it did not cross the line now, so rates count from here.
     */
    default void resumed(FileHeader file, long offset) {
    }
}
