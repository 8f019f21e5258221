package org.ripv.messages;

import java.io.Serializable;

/**
 * A typed result in a {@link Footer}. The set is closed so that the object streams can accept
 * exactly these classes and nothing else.
 */
public sealed interface Result extends Serializable
        permits FileListing, FileData, FileBundle, ImageResult, TableResult, ServiceList, MailboxList,
        MailboxStatus, Progress, SessionInfo, UpdateCount, ConsoleBatch, NotifyList {
}
