package org.ripv.services.ingest;

/**
 * A file whose sensor list is factored out into a cache file ({@code CRC.cac}) this shore does
 * not hold yet: not broken, but not decodable until the cache arrives.
 */
public final class MissingSensorListException extends SlocumFormatException {
    private static final long serialVersionUID = 1L;
    private final String crc;

    public MissingSensorListException(String file, long offset, String crc) {
        super(file, offset, "its sensor list is in the cache file " + crc + ".cac, which this server does not hold yet:"
                + " fetch it from the glider (ymodem:get " + crc + ".cac, in its state/cache folder) or upload it");
        this.crc = crc;
    }

    /** The missing cache's CRC, as the file's header writes it (lower case). */
    public String crc() {
        return crc;
    }
}
