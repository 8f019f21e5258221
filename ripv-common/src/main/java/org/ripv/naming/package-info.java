/**
 * Appendix A names: {@code <Service>::<host>} service names and {@code <Service>::<host>HANDLE} MailBox addresses, and how handles are chosen.
 */
package org.ripv.naming;
