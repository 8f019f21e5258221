/**
 * {@code java -jar ripv-services.jar SERVICE}: launches the SerialPortServer, DatabaseServer, DataVisServer or the glider simulator (thesis names and forms too).
 */
package org.ripv.services;
