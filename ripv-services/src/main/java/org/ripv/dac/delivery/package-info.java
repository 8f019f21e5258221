/**
 * DAC delivery on arrival (issue 37 item 4, docs/dac.md#delivery-on-arrival): a deployment
 * configured on the DatabaseServer ({@code --dac FILE}) turns each call's Slocum files, as the
 * ingest stores them, into profile files, checks each and pushes it to the DAC.
 *
 * <p>{@link org.ripv.dac.delivery.Deployment} reads and checks the deployment file (metadata,
 * QC, destination) before anything runs; {@link org.ripv.dac.delivery.Delivery} is one running
 * deployment: files kept by segment, profiles written once (a delayed-mode file replacing its
 * real-time one), checked, pushed with the ledger and retried with back-off on a thread of its
 * own, so an ingest never waits for the DAC; {@link org.ripv.dac.delivery.DeliveryState} is what
 * {@code dac:status} (and the server's {@code ?dac MAILBOX}) shows; {@link org.ripv.dac.delivery.Deliveries}
 * is the DatabaseServer's one hook.
 */
package org.ripv.dac.delivery;
