package org.ripv.messages;

import java.util.List;

/** Several whole files from one command (a YMODEM batch). The server stores them. */
public record FileBundle(List<FileData> files) implements Result {
    public FileBundle {
        files = List.copyOf(files);
    }
}
