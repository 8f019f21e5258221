/**
 * Vehicles called by their names: wherever a server command expects a MailBox ({@code ?status},
 * {@code ?lock}, {@code ?history}, {@code ?watch}, {@code ?queue}…), a vehicle's name (its link's
 * {@code name=}, e.g. {@code sim01}) or a handle ({@code ttyS0}) stands for the one MailBox that
 * has it. {@link org.ripv.server.vehicles.MailboxArgument} says which word of a command is the
 * MailBox, {@link org.ripv.server.vehicles.VehicleNames} turns the word into a full address
 * against the MailBoxes the services list, or says what is wrong: an ambiguous name lists the
 * candidates, an unknown one the names there are. Resolving on the server gives the CLI, the GUI
 * and any other client the same names.
 */
package org.ripv.server.vehicles;
