// What the permit file lets this user send (GET /api/rights): pages show the controls the rules allow, whatever the
// user's roles are called. Only tidiness: the server decides every command again when it is sent.

/** { send, commands: {COMMAND: bool} } for the MailBox ('' for the server's own commands). */
export async function rights(mailbox, commands = []) {
  const q = new URLSearchParams({ m: mailbox });
  commands.forEach((c) => q.append('c', c));
  const r = await fetch(`/api/rights?${q}`, { credentials: 'same-origin' });
  if (!r.ok) return { send: false, commands: Object.fromEntries(commands.map((c) => [c, false])) };
  return r.json();
}
