/**
 * The server closing the loop between its services: DBA files a SerialPortServer downloads are
 * ingested into a DatabaseServer as soon as they land ({@link org.ripv.server.dataloop.DataLoop},
 * configured by {@code DATA/ingest.properties}), through requests the server sends on the fetching
 * user's behalf ({@link org.ripv.server.dataloop.ServiceCalls}). docs/database.md.
 *
 * <p>Threads: none of its own. {@code downloaded} runs on the RMI thread that delivered the
 * download's reply; the ingest's answer is handled on the RMI thread that delivers it.
 */
package org.ripv.server.dataloop;
