package org.ripv.messages;

import java.util.Objects;

/** A picture (a DataVisServer plot): its file name and the JPEG bytes. */
public record ImageResult(String name, byte[] jpeg) implements Result {
    public ImageResult {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(jpeg, "jpeg");
    }

    @Override
    public String toString() {
        return "ImageResult[" + name + ", " + jpeg.length + " bytes]";
    }
}
