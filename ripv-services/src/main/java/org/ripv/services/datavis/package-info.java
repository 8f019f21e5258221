/**
 * The DataVisServer (SID 999999): {@code vis:NAME} turns an uploaded data file into a JPEG through
 * the thesis's file exchange ({@code data.dat}, {@code info.dat}, {@code <output>.jpg},
 * {@code ok.dat}) with a plot worker: the built-in JFreeChart {@link org.ripv.services.datavis.PlotWorker},
 * {@code octave-cli} on {@code ripvOut.m} supervised by {@link org.ripv.services.datavis.OctaveWorker},
 * or one started by hand. Protocol and data format: docs/datavis.md.
 *
 * <p>Threads: the MailBox's inbox assistant runs a plot and waits on a {@code WatchService} for
 * {@code ok.dat}; {@code ripv-datavis-worker-<dir>} is the built-in worker;
 * {@code ripv-datavis-octave-supervisor} restarts Octave and {@code ripv-datavis-octave-output-<pid>}
 * logs what it prints.
 */
package org.ripv.services.datavis;
