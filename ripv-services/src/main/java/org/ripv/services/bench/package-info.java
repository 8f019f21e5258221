/**
 * Benchmarks of the services, runnable mains rather than tests (YMODEM throughput over a
 * baud-paced relay).
 */
package org.ripv.services.bench;
