package org.ripv.messages;

import java.io.Serializable;
import java.util.Objects;

/**
 * A file carried inside a request: the server attaches a file from its upload directory to a
 * command that names one (see {@link ServiceDescriptor#attachPrefixes()}).
 */
public record Attachment(String name, byte[] data) implements Serializable {
    public Attachment {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(data, "data");
    }

    @Override
    public String toString() {
        return "Attachment[" + name + ", " + data.length + " bytes]";
    }
}
