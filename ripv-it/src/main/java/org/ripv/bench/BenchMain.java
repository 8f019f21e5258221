package org.ripv.bench;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code ./ripv bench [broker|...]}: the benchmarks whose figures docs/performance.md records. */
@Command(name = "ripv-bench", mixinStandardHelpOptions = true,
        description = "RIPV benchmarks. Each reports ratios against a baseline measured in the same run.",
        subcommands = {BrokerBench.class})
public final class BenchMain implements Runnable {
    @Override
    public void run() {
        new CommandLine(new BrokerBench()).execute();
    }

    public static void main(String[] args) {
        System.exit(new CommandLine(new BenchMain()).execute(args));
    }
}
