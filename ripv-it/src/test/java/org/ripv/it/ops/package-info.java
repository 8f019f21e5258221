/** Tests of the operator's tools as users run them: the ripv script, the interactive CLI in a terminal, the docs' commands. */
package org.ripv.it.ops;
