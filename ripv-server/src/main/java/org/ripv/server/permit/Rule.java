package org.ripv.server.permit;

import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;
import org.ripv.commands.SingleLineCommand;

/**
 * One {@code allow} or {@code deny} line of the permit file:
 * {@code allow WHO SERVICE MAILBOX COMMAND-PATTERN}. WHO is a user, {@code @role} or {@code *};
 * SERVICE is a service's short name ({@code SerialPortServer}, {@code RIPVServer} for the server's
 * own commands) or a glob; MAILBOX is a handle glob ({@code ttyS0}, {@code *}); the pattern, the
 * rest of the line, is a case-insensitive glob over the whole command ({@code ymodem:get *}).
 */
record Rule(boolean allow, String who, Pattern service, Pattern mailbox, Pattern command, String source) {

    static Rule parse(boolean allow, String who, String service, String mailbox, String command, String source) {
        return new Rule(allow, who, glob(service), glob(mailbox), glob(command.trim()), source);
    }

    boolean appliesTo(String user, List<String> roles) {
        return who.equals("*") || who.equals(user) || (who.startsWith("@") && roles.contains(who.substring(1)));
    }

    boolean matches(String serviceName, String handle, String commandText) {
        // A rule speaks about one line: text holding a line break or other control character
        // matches no rule, so it can only ever be refused (the server refuses it earlier anyway).
        if (SingleLineCommand.firstControl(commandText) >= 0) {
            return false;
        }
        return service.matcher(serviceName).matches() && mailbox.matcher(handle).matches()
                && command.matcher(commandText.strip()).matches();
    }

    /**
     * A glob: {@code *} matches any run; everything else is literal, case-insensitive. ({@code ?}
     * is literal so that rules can name the server's {@code ?} commands.) No DOTALL: {@code *}
     * never runs across a line break, so {@code dir*} cannot match {@code dir\rGO}.
     */
    static Pattern glob(String g) {
        StringBuilder re = new StringBuilder();
        for (char c : g.toCharArray()) {
            re.append(c == '*' ? ".*" : Pattern.quote(String.valueOf(c)));
        }
        return Pattern.compile(re.toString(), Pattern.CASE_INSENSITIVE | Pattern.UNICODE_CASE);
    }

    @Override
    public String toString() {
        return source.toLowerCase(Locale.ROOT).startsWith("allow") || source.toLowerCase(Locale.ROOT).startsWith("deny")
                ? source : (allow ? "allow " : "deny ") + source;
    }
}
