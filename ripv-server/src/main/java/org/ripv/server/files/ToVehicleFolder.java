package org.ripv.server.files;

import java.nio.file.Path;

/**
 * The names of the upload store's {@code to-vehicle/} folders (issue 24, item 3): a file for a
 * vehicle is uploaded as {@code to-vehicle/FOLDER/NAME}, FOLDER being its MailBox's folder as
 * {@code ?dlfiles} names it ({@link FileStore#folderFor}), and moves to
 * {@code to-vehicle/FOLDER/sent/NAME} once the vehicle has it. Nothing else with a slash is an
 * upload name; each part follows {@link FileNames}, so no name leaves its folder.
 */
public final class ToVehicleFolder {
    /** The upload store's folder of files waiting for vehicles. */
    public static final String DIR = "to-vehicle";
    /** Inside a MailBox's folder, the files its vehicle has. */
    public static final String SENT = "sent";

    /** A checked to-vehicle name: the MailBox's folder and the plain file name. */
    public record Name(String folder, String file) {
        @Override
        public String toString() {
            return DIR + "/" + folder + "/" + file;
        }

        Path in(Path uploadDir) {
            return uploadDir.resolve(DIR).resolve(folder).resolve(file);
        }
    }

    private ToVehicleFolder() {}

    /** Whether an upload name means a to-vehicle folder (and so must be {@link #parse}d). */
    public static boolean isToVehicle(String name) {
        return name != null && name.startsWith(DIR + "/");
    }

    /** {@code to-vehicle/FOLDER/NAME}, or an error quoting the name and saying what is wanted. */
    public static Name parse(String name) {
        String[] parts = name.split("/", -1);
        if (parts.length != 3 || !parts[0].equals(DIR)) {
            throw new IllegalArgumentException("'" + name + "' is not a to-vehicle name: give " + DIR + "/FOLDER/NAME, FOLDER"
                    + " being the vehicle's folder as ?dlfiles names it (HANDLE@HOST@SERVICE) and NAME a plain file name");
        }
        try {
            FileNames.check(parts[1]);
            FileNames.check(parts[2]);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("'" + name + "' is not a to-vehicle name: " + e.getMessage());
        }
        if (parts[2].equals(SENT)) {
            throw new IllegalArgumentException("'" + name + "': '" + SENT + "' is the folder of files already sent; give another name");
        }
        return new Name(parts[1], parts[2]);
    }
}
