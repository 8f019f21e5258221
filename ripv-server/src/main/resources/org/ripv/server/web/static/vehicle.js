// A vehicle's live console (the stream --follow gives), scroll-back, and a command line with the user's rights.
// Vehicle text is only ever set with textContent: a line of HTML stays a line of text.
import { session, PostOffice, bar } from './postoffice.js';
import { mailboxParam } from './ui.js';
import { command } from './address.js';

const { mailbox } = mailboxParam(); // one MailBox address or the page stops, saying the link's name is not valid
const s = await session();
bar(s);
document.getElementById('name').textContent = mailbox;
document.title = `RIPV ${mailbox}`;
const po = new PostOffice(s.csrf);
const consoleBox = document.getElementById('console');
const stateLine = document.getElementById('state');
const search = document.getElementById('search');
let running = null; // the id of the request under way

function line(text, cls, time) {
  const div = document.createElement('div');
  div.className = cls;
  div.textContent = (time ? new Date(time).toISOString().substring(11, 19) + ' ' : '') + text;
  if (search.value && !div.textContent.includes(search.value)) div.hidden = true;
  return div;
}

// Events that say something did not happen as asked, in the error colour (a run DONE_WITH_ERRORS is not DONE).
const BAD_EVENTS = new Set(['ALERT', 'LINK_LOST', 'TRANSFER_FAILED', 'WORKFLOW_FAILED', 'WORKFLOW_DONE_WITH_ERRORS']);

function entryLine(e) {
  const text = e.kind === 'COMMAND' ? `${e.user}> ${e.text}` : e.kind === 'EVENT' ? `[${e.event}] ${e.text}` : e.text;
  return line(text, e.kind === 'EVENT' && BAD_EVENTS.has(e.event) ? 'EVENT error' : e.kind, e.time);
}

function append(nodes) {
  const atEnd = consoleBox.scrollTop + consoleBox.clientHeight >= consoleBox.scrollHeight - 30;
  consoleBox.append(...nodes);
  while (consoleBox.childElementCount > 5000) consoleBox.firstElementChild.remove();
  if (atEnd) consoleBox.scrollTop = consoleBox.scrollHeight;
}

po.onPush = (m) => {
  if (m.result?.kind === 'ConsoleBatch' && m.result.mailbox === mailbox) append(m.result.entries.map(entryLine));
  if (m.result?.kind === 'ConsoleBatch') {
    for (const e of m.result.entries) {
      if (e.event === 'LOCK_TAKEN') setLock(e.user);
      if (e.event === 'LOCK_RELEASED') setLock('');
    }
  }
};
po.onClose = (why) => { stateLine.textContent = `Disconnected: ${why}. Reload the page to reconnect.`; };

function setLock(holder) {
  document.getElementById('lock').textContent = holder ? `Lock: held by ${holder}` : 'Lock: free';
}

function reply(m) {
  const cls = m.status === 'ERROR' ? 'error' : 'reply';
  const nodes = [line(m.status === 'ERROR' ? `Error: ${m.text}` : m.text, cls)];
  const r = m.result;
  if (r?.kind === 'FileListing') r.files.forEach((f) => nodes.push(line(`  ${f.name ?? JSON.stringify(f)}`, cls)));
  append(nodes.filter((n) => n.textContent));
}

const watching = await po.send('', command('?watch', mailbox));
if (watching.status === 'ERROR') {
  stateLine.textContent = `Error: ${watching.text}`;
} else {
  stateLine.textContent = watching.text;
  append((watching.result?.entries || []).map(entryLine));
}
const status = await po.send('', command('?status', mailbox));
setLock(status.result?.lockedBy || '');

const observer = s.roles.length > 0 && s.roles.every((r) => r === 'observers');
if (observer) {
  document.getElementById('command-form').hidden = true;
  document.getElementById('observer').hidden = false;
}

const progress = document.getElementById('progress');
const cancel = document.getElementById('cancel');
document.getElementById('command-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  const input = document.getElementById('command');
  const body = input.value.trim();
  if (!body) return;
  input.value = '';
  cancel.disabled = false;
  const target = body.startsWith('?') ? '' : mailbox;
  const done = po.send(target, body, document.getElementById('priority').value, (p) => {
    const r = p.result;
    progress.textContent = r?.kind === 'Progress' && r.total > 0
      ? `${r.what}: ${Math.round((100 * r.done) / r.total)} %` + (r.ratePerSecond > 0 ? `, ETA ${Math.round((r.total - r.done) / r.ratePerSecond)} s` : '')
      : p.text;
  });
  running = po.lastId;
  reply(await done);
  running = null;
  cancel.disabled = true;
  progress.textContent = '';
});

async function cancelRunning() {
  if (running == null) return;
  reply(await po.send('', command('?cancel', String(running))));
}
cancel.addEventListener('click', cancelRunning);
document.addEventListener('keydown', (e) => { if (e.key === 'Escape') cancelRunning(); });
document.getElementById('take-lock').addEventListener('click', async () => reply(await po.send('', command('?lock', mailbox))));
document.getElementById('release-lock').addEventListener('click', async () => reply(await po.send('', command('?unlock', mailbox))));
document.getElementById('earlier').addEventListener('click', async () => {
  const h = await po.send('', command('?history', mailbox, '--last', '1000'));
  if (h.status === 'ERROR') { reply(h); return; }
  consoleBox.replaceChildren(...(h.result?.entries || []).map(entryLine));
});
search.addEventListener('input', () => {
  for (const div of consoleBox.children) div.hidden = !!search.value && !div.textContent.includes(search.value);
});
