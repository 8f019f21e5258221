/**
 * The TaskManager base class: the header side runs a request, the footer side delivers a reply. The server's and the services' TaskManagers extend it.
 */
package org.ripv.managers;
