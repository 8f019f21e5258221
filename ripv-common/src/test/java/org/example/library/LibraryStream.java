package org.example.library;

import java.io.ByteArrayInputStream;
import java.io.ObjectInputStream;

/** Stands for a library that reads its own object streams, as Derby does while it creates tables. */
public final class LibraryStream {
    private LibraryStream() {}

    public static Object read(byte[] bytes) throws Exception {
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes))) {
            return in.readObject();
        }
    }
}
