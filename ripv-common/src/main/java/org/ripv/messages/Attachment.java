package org.ripv.messages;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.Serializable;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.zip.CRC32;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;
import java.util.zip.ZipOutputStream;

/**
 * A file carried inside a request: the server attaches a file from its upload directory to a
 * command that names one (see {@link ServiceDescriptor#attachPrefixes()}), or several files from
 * its download directory as one {@linkplain #bundle bundle} (see
 * {@link ServiceDescriptor#downloadPrefixes()}).
 */
public record Attachment(String name, byte[] data) implements Serializable {
    /** The name of an attachment that bundles several files. */
    public static final String BUNDLE = "files.zip";

    public Attachment {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(data, "data");
    }

    /** Several files as one attachment: a ZIP archive with one stored (uncompressed) entry per file, in order. */
    public static Attachment bundle(List<Attachment> files) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (ZipOutputStream zip = new ZipOutputStream(out)) {
            zip.setMethod(ZipOutputStream.STORED);
            for (Attachment f : files) {
                ZipEntry e = new ZipEntry(f.name());
                CRC32 crc = new CRC32();
                crc.update(f.data());
                e.setSize(f.data().length);
                e.setCompressedSize(f.data().length);
                e.setCrc(crc.getValue());
                zip.putNextEntry(e);
                zip.write(f.data());
                zip.closeEntry();
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a byte array does not fail
        }
        return new Attachment(BUNDLE, out.toByteArray());
    }

    /**
     * The files of a {@link #bundle}, at most {@code maxFiles} of them.
     *
     * @throws IOException when this is not a bundle
     */
    public List<Attachment> files(int maxFiles) throws IOException {
        if (!name.equals(BUNDLE)) {
            return List.of(this);
        }
        List<Attachment> out = new ArrayList<>();
        try (ZipInputStream zip = new ZipInputStream(new ByteArrayInputStream(data))) {
            for (ZipEntry e = zip.getNextEntry(); e != null; e = zip.getNextEntry()) {
                if (out.size() == maxFiles) {
                    throw new IOException("the bundle holds more than " + maxFiles + " files");
                }
                out.add(new Attachment(e.getName(), zip.readAllBytes()));
            }
        }
        return out;
    }

    @Override
    public String toString() {
        return "Attachment[" + name + ", " + data.length + " bytes]";
    }
}
