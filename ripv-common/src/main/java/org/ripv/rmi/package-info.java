/**
 * The RMI contract between the server and its services ({@link org.ripv.rmi.GenericRMIInterface}) and the RMI settings every RIPV process uses.
 */
package org.ripv.rmi;
