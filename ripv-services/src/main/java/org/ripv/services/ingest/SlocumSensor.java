package org.ripv.services.ingest;

/** One sensor of a Slocum binary file's cycle: its name, units and value size (1, 2, 4 or 8 bytes). */
public record SlocumSensor(String name, String units, int bytes) {}
