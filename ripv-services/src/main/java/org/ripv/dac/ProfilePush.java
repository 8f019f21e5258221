package org.ripv.dac;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * Sends profile files to a DAC drop ({@link SftpPush}, {@link FtpsPush}): each file checked first,
 * uploaded under a temporary name and renamed when whole, every outcome in the ledger, and a file
 * the ledger has as sent with the same bytes never sent again.
 */
public interface ProfilePush {
    /** One outcome a file: {@code sent}, {@code already sent}, {@code not sent} (failed the check) or {@code failed}. */
    List<SftpPush.Outcome> push(List<Path> files) throws IOException, InterruptedException;
}
