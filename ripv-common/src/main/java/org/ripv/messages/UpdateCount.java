package org.ripv.messages;

/** The answer to an SQL update: how many rows it changed. */
public record UpdateCount(long count) implements Result {}
