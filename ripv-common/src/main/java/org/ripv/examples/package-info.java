/**
 * The example ClockService that docs/extending.md walks through.
 */
package org.ripv.examples;
