package org.ripv.server.routing;

import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.server.files.FileStore;
import org.ripv.server.files.ToVehicleFolder;

/**
 * Step 8: {@code tovehicle:put} sends a vehicle only a file of its own folder
 * (docs/serial.md#the-to-vehicle-folder).
 */
final class ToVehicleFolderRule implements AdmissionStep {
    static final String COMMAND = "tovehicle:put";

    @Override
    public Verdict check(Admitting a) {
        String body = a.body().trim();
        if (!body.startsWith(COMMAND)) {
            return Verdict.PASS; // most commands: decided without splitting the body
        }
        String ownFolder = ToVehicleFolder.DIR + "/" + FileStore.folderFor(a.address().toString()) + "/";
        String[] words = body.split("\\s+");
        if (words[0].equals(COMMAND) && (words.length != 2 || !words[1].startsWith(ownFolder))) {
            return Verdict.refuse(a.refuse(ErrorCode.BAD_FILE_NAME, COMMAND + " sends a file of " + a.address() + "'s own folder, "
                    + ownFolder + "NAME; not '" + Header.abbreviate(body) + "'"));
        }
        return Verdict.PASS;
    }
}
