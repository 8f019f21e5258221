package org.ripv.server.routing;

import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.util.function.Supplier;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.server.dataloop.DataLoop;
import org.ripv.server.files.DownloadAttachments;
import org.ripv.server.files.DownloadRights;
import org.ripv.server.files.FileStore;
import org.ripv.server.files.FileTooLargeException;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.permit.SecurityRefusal;

/**
 * Step 9: the file(s) a command names travel with it — download-directory files after one of
 * the service's download prefixes ({@code ingest NAME…}, with the read right on each file's
 * MailBox), or an upload-directory file after one of its attach prefixes ({@code put NAME}).
 */
record AttachmentRule(FileStore files, Supplier<PermitFile> permits) implements AdmissionStep {
    @Override
    public Verdict check(Admitting a) {
        String sid = a.sid();
        try {
            a.attachment(attachmentFor(a.service().descriptor(), a.body(), a.userName()));
            return Verdict.PASS;
        } catch (SecurityRefusal e) {
            return Verdict.refuse(a.refuse(ErrorCode.FORBIDDEN, e.getMessage()));
        } catch (FileTooLargeException e) {
            return Verdict.refuse(a.refuse(ErrorCode.TOO_LARGE, e.getMessage()));
        } catch (NoSuchFileException e) {
            return Verdict.refuse(a.refuse(ErrorCode.BAD_FILE_NAME, DataLoop.noSuchFile(sid, a.body(), e.getMessage())));
        } catch (IllegalArgumentException e) {
            return Verdict.refuse(a.refuse(ErrorCode.BAD_FILE_NAME, e.getMessage()));
        } catch (IOException e) {
            return Verdict.refuse(a.refuse(ErrorCode.INTERNAL, "could not read the upload: " + e.getMessage()));
        }
    }

    /** The file(s) {@code body} names after one of the service's prefixes, or null. */
    private Attachment attachmentFor(ServiceDescriptor d, String body, String user) throws IOException {
        Attachment downloads = DownloadAttachments.forCommand(files, d, body,
                name -> DownloadRights.check(files, permits.get(), user, name));
        if (downloads != null) {
            return downloads;
        }
        String trimmed = body.trim();
        for (String prefix : d.attachPrefixes()) {
            if (trimmed.regionMatches(true, 0, prefix, 0, prefix.length())) {
                String rest = trimmed.substring(prefix.length()).trim();
                if (rest.isEmpty()) {
                    throw new IllegalArgumentException("'" + prefix.trim() + "' needs the name of a file in the upload directory");
                }
                String name = rest.split("\\s+", 2)[0];
                return new Attachment(name, files.readUpload(name));
            }
        }
        return null;
    }
}
