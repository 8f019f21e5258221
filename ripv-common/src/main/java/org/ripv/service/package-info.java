/**
 * What a service author uses: extend {@link org.ripv.service.RIPVService}, open MailBoxes with {@link org.ripv.service.CommandHandler}s, answer with {@link org.ripv.service.Reply}, and register with {@link org.ripv.service.ServiceConnector}. See docs/extending.md.
 */
package org.ripv.service;
