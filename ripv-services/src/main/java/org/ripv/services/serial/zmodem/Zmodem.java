package org.ripv.services.serial.zmodem;

/** ZMODEM's constants (Chuck Forsberg's zmodem.h, as lrzsz uses them). */
public final class Zmodem {
    private Zmodem() {
    }

    static final int ZPAD = '*';
    static final int ZDLE = 0x18;
    static final int ZBIN = 'A';
    static final int ZHEX = 'B';
    static final int ZBIN32 = 'C';
    static final int XON = 0x11;

    public static final int ZRQINIT = 0;
    public static final int ZRINIT = 1;
    public static final int ZSINIT = 2;
    public static final int ZACK = 3;
    public static final int ZFILE = 4;
    public static final int ZSKIP = 5;
    public static final int ZNAK = 6;
    public static final int ZABORT = 7;
    public static final int ZFIN = 8;
    public static final int ZRPOS = 9;
    public static final int ZDATA = 10;
    public static final int ZEOF = 11;
    public static final int ZFERR = 12;
    public static final int ZCRC = 13;
    public static final int ZCHALLENGE = 14;
    public static final int ZCOMPL = 15;
    public static final int ZCAN = 16;
    public static final int ZFREECNT = 17;
    public static final int ZCOMMAND = 18;
    public static final int ZSTDERR = 19;

    private static final String[] NAMES = {"ZRQINIT", "ZRINIT", "ZSINIT", "ZACK", "ZFILE", "ZSKIP", "ZNAK", "ZABORT",
        "ZFIN", "ZRPOS", "ZDATA", "ZEOF", "ZFERR", "ZCRC", "ZCHALLENGE", "ZCOMPL", "ZCAN", "ZFREECNT", "ZCOMMAND",
        "ZSTDERR"};

    /** Data subpacket ends: end of frame, go on (streaming), go on and ACK, wait for ACK. */
    public static final int ZCRCE = 'h';
    public static final int ZCRCG = 'i';
    public static final int ZCRCQ = 'j';
    public static final int ZCRCW = 'k';
    static final int ZRUB0 = 'l';
    static final int ZRUB1 = 'm';

    /** ZRINIT capability flags (ZF0). */
    static final int CANFDX = 0x01;
    static final int CANOVIO = 0x02;
    static final int CANFC32 = 0x20;
    static final int ESCCTL = 0x40;

    /** ZFILE conversion (ZF0): binary. */
    static final int ZCBIN = 1;

    /** The longest data subpacket accepted (lrzsz sends 1024, 8192 with -8). */
    public static final int MAX_SUBPACKET = 8192;

    /** What lrzsz's {@code canit} sends: aborts the peer and any shell on the line (eight CANs, ten backspaces). */
    static final byte[] ABORT = {0x18, 0x18, 0x18, 0x18, 0x18, 0x18, 0x18, 0x18, 8, 8, 8, 8, 8, 8, 8, 8, 8, 8};

    static String name(int type) {
        return type >= 0 && type < NAMES.length ? NAMES[type] : "type " + type;
    }
}
