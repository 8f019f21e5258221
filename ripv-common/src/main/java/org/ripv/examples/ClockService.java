package org.ripv.examples;

import java.time.Instant;
import java.util.concurrent.Callable;
import org.ripv.messages.ErrorCode;
import org.ripv.naming.Handles;
import org.ripv.service.RIPVService;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.ripv.service.ServiceLaunchOptions;
import org.ripv.launch.Launchers;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

/**
 * The smallest useful RIPV service, walked through in {@code docs/extending.md}: one MailBox
 * that tells the time, echoes text, and sleeps (for trying priorities and locks).
 */
public final class ClockService extends RIPVService {
    /** The SID of the example; a real service picks its own unused six digits. */
    public static final String SID = "100100";

    public ClockService(String host) {
        super("ClockService", SID, host);
    }

    @Override
    protected String description() {
        return "Example service: time, echo TEXT, sleep MILLIS";
    }

    @Override
    protected void open() {
        openMailBox(Handles.platformDefault(), this::execute);
    }

    private Reply execute(Request request) throws InterruptedException {
        String command = request.command().trim();
        String word = command.split("\\s+", 2)[0];
        String rest = command.substring(word.length()).trim();
        switch (word) {
            case "time":
                return Reply.ok(Instant.now().toString());
            case "echo":
                return Reply.ok(rest);
            case "sleep":
                long millis;
                try {
                    millis = Long.parseLong(rest);
                } catch (NumberFormatException e) {
                    return Reply.error(ErrorCode.BAD_REQUEST, "sleep takes milliseconds, got '" + rest + "'");
                }
                Thread.sleep(Math.min(millis, 60_000));
                return Reply.ok("slept " + millis + " ms");
            default:
                return Reply.error(ErrorCode.UNKNOWN_COMMAND,
                        "ClockService knows time, echo TEXT and sleep MILLIS, not '" + word + "'");
        }
    }

    @Command(name = "clock-service", mixinStandardHelpOptions = true,
            description = "Registers the example ClockService with a RIPVServer.")
    static final class Launch implements Callable<Integer> {
        @Mixin
        ServiceLaunchOptions launch;

        @Override
        public Integer call() throws Exception {
            return launch.serve(new ClockService(launch.hostName()));
        }
    }

    public static void main(String[] args) {
        CommandLine cl = Launchers.commandLine(new Launch(), "ripv service clock");
        System.exit(cl.execute(ServiceLaunchOptions.thesisForm(args)));
    }
}
