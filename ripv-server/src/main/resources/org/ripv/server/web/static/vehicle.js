// A vehicle's live console (the stream --follow gives), scroll-back, its call state with the dive countdown, the keys
// the link allows, and a command line with the user's rights. Vehicle text is only ever set with textContent: a line
// of HTML stays a line of text.
import { session, PostOffice, bar } from './postoffice.js';
import { CallState, linkKeys } from './callstate.js';
import { rights } from './rights.js';
import { clock } from './time.js';
import { mailboxParam } from './ui.js';
import { command } from './address.js';
import { SurfacingView } from './vehicle-surfacing.js';

const { mailbox } = mailboxParam(); // one MailBox address or the page stops, saying the link's name is not valid
const s = await session();
bar(s);
document.getElementById('name').textContent = mailbox;
document.title = `RIPV ${mailbox}`;
const po = new PostOffice(s.csrf);
const $ = (id) => document.getElementById(id);
const consoleBox = $('console');
const stateLine = $('state');
const search = $('search');
const call = new CallState();
const calls = new SurfacingView(po, mailbox); // the last call's record, trends, track and waypoint
let running = null; // the id of the request this page started and is waiting for
let vehicleLines = 0; // the vehicle's lines and transfer notes shown so far: a command's output arrives as these

function line(text, cls, time) {
  const div = document.createElement('div');
  div.className = cls;
  div.textContent = (time ? `${clock(time)} ` : '') + text;
  if (search.value && !div.textContent.includes(search.value)) div.hidden = true;
  return div;
}

// Events that say something did not happen as asked, in the error colour (a run DONE_WITH_ERRORS is not DONE).
const BAD_EVENTS = new Set(['ALERT', 'LINK_LOST', 'TRANSFER_FAILED', 'WORKFLOW_FAILED', 'WORKFLOW_DONE_WITH_ERRORS']);

function entryLine(e) {
  call.takeEntry(e);
  calls.take(e);
  if (e.kind === 'LINE' || e.kind === 'TRANSFER') vehicleLines++;
  const text = e.kind === 'COMMAND' ? `${e.user}> ${e.text}` : e.kind === 'EVENT' ? `[${e.event}] ${e.text}` : e.text;
  return line(text, e.kind === 'EVENT' && BAD_EVENTS.has(e.event) ? 'EVENT error' : e.kind, e.time);
}

function append(nodes) {
  const atEnd = consoleBox.scrollTop + consoleBox.clientHeight >= consoleBox.scrollHeight - 30;
  consoleBox.append(...nodes);
  while (consoleBox.childElementCount > 5000) consoleBox.firstElementChild.remove();
  if (atEnd) consoleBox.scrollTop = consoleBox.scrollHeight;
}

/** The badge and the countdown, from the call state the page holds. */
function showCall() {
  const badge = $('badge');
  badge.className = `badge ${call.state}`;
  badge.textContent = call.words();
  const left = call.secondsLeft();
  $('dives-in').hidden = left == null;
  $('dives-in').textContent = left == null ? '' : `dives in ${left} s`;
}
setInterval(showCall, 1000);

let keysAllowed = [];
/** The MailBox's status: lock holder, call state and the keys its link takes. */
async function refreshStatus() {
  const st = await po.send('', command('?status', mailbox));
  const r = st.result;
  setLock(r?.lockedBy || '');
  call.takeSession(r?.session);
  const keys = linkKeys(r?.detail);
  if (keys.join() !== keysAllowed.join()) {
    keysAllowed = keys;
    await showKeys(keys);
  }
  showCall();
}

po.onPush = (m) => {
  const r = m.result;
  if (r?.kind === 'ConsoleBatch' && r.mailbox === mailbox) {
    append(r.entries.map(entryLine));
    showCall();
    if (r.entries.some((e) => e.kind === 'EVENT')) refreshStatus(); // the state (and its diveAt) as the server has it now
  }
  if (r?.kind === 'ConsoleBatch') {
    for (const e of r.entries) {
      if (e.mailbox && e.mailbox !== mailbox) continue;
      if (e.event === 'LOCK_TAKEN') setLock(e.user);
      if (e.event === 'LOCK_RELEASED') setLock('');
    }
  }
  if (r?.session && (r.address === mailbox || m.mailbox === mailbox)) { call.takeSession(r.session); showCall(); }
};
po.onClose = (why) => { stateLine.textContent = `Disconnected: ${why}. Reload the page to reconnect.`; };

function setLock(holder) {
  $('lock').textContent = holder ? `Lock: held by ${holder}` : 'Lock: free';
}

function reply(m) {
  const cls = m.status === 'ERROR' ? 'error' : 'reply';
  const nodes = [line(m.status === 'ERROR' ? `Error: ${m.text}` : m.text, cls)];
  const r = m.result;
  if (r?.kind === 'FileListing') r.files.forEach((f) => nodes.push(line(`  ${f.name ?? JSON.stringify(f)}`, cls)));
  append(nodes.filter((n) => n.textContent));
}

/**
 * A vehicle command's reply. What the vehicle printed reaches the console as its own lines, so an OK reply is shown only
 * when no line came with it (a service that does not publish its output): the output shows once.
 */
async function vehicleReply(m, linesBefore) {
  if (m.status === 'OK' && vehicleLines === linesBefore) await new Promise((r) => setTimeout(r, 400)); // a line may trail its reply
  if (m.status !== 'OK' || vehicleLines === linesBefore) reply(m);
}

const watching = await po.send('', command('?watch', mailbox));
if (watching.status === 'ERROR') {
  stateLine.textContent = `Error: ${watching.text}`;
} else {
  stateLine.textContent = 'watching live';
  append((watching.result?.entries || []).map(entryLine));
}

const progress = $('progress');
const cancel = $('cancel');
async function send(typed, priority) {
  // "?key ctrl-c" typed here means this page's vehicle: the server's ?key wants the MailBox's address first.
  const key = /^\?key\s+(ctrl-[a-z])$/i.exec(typed);
  const body = key ? command('?key', mailbox, key[1].toLowerCase()) : typed;
  const target = body.startsWith('?') ? '' : mailbox;
  const before = vehicleLines;
  const req = po.send(target, body, priority, (p) => {
    const r = p.result;
    progress.textContent = r?.kind === 'Progress' && r.total > 0
      ? `${r.what}: ${Math.round((100 * r.done) / r.total)} %` + (r.ratePerSecond > 0 ? `, ETA ${Math.round((r.total - r.done) / r.ratePerSecond)} s` : '')
      : p.text;
  });
  running = req.id;
  cancel.disabled = false;
  const m = await req;
  if (running === req.id) {
    running = null;
    cancel.disabled = true;
    progress.textContent = '';
  }
  if (target || key) await vehicleReply(m, before); else reply(m); // a key's answer is the vehicle's lines too
}

$('command-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  const input = $('command');
  const body = input.value.trim();
  if (!body) return;
  input.value = '';
  await send(body, $('priority').value);
});

async function cancelRunning() {
  if (running == null) return;
  reply(await po.cancel(running));
}
cancel.addEventListener('click', cancelRunning);
document.addEventListener('keydown', (e) => { if (e.key === 'Escape') cancelRunning(); });
$('take-lock').addEventListener('click', async () => reply(await po.send('', command('?lock', mailbox))));
$('release-lock').addEventListener('click', async () => reply(await po.send('', command('?unlock', mailbox))));
$('earlier').addEventListener('click', async () => {
  const h = await po.send('', command('?history', mailbox, '--last', '1000'));
  if (h.status === 'ERROR') { reply(h); return; }
  consoleBox.replaceChildren(...(h.result?.entries || []).map(entryLine));
});
search.addEventListener('input', () => {
  for (const div of consoleBox.children) div.hidden = !!search.value && !div.textContent.includes(search.value);
});

// A key goes to this page's MailBox as ?key MAILBOX KEY, urgent: the dive does not wait behind a queue.
async function showKeys(keys) {
  const may = keys.length ? (await rights(mailbox, keys.map((k) => `?key ${k}`))).commands : {};
  const allowed = keys.filter((k) => may[`?key ${k}`]);
  $('keys').replaceChildren(...allowed.map((k) => {
    const b = document.createElement('button');
    b.type = 'button';
    b.className = 'secondary key';
    b.textContent = k.replace(/^ctrl-(.)$/, (_, c) => `Ctrl-${c.toUpperCase()}`);
    b.title = `Press ${b.textContent} on the vehicle (?key ${k})`;
    b.addEventListener('click', async () => {
      const before = vehicleLines;
      await vehicleReply(await po.send('', command('?key', mailbox, k), 'urgent'), before);
    });
    return b;
  }));
  $('keys').hidden = allowed.length === 0;
  mayUseKeys = allowed.length > 0;
  showRights();
}

// The controls the permit file's rules allow this user, not the ones a role's name suggests.
let maySend = false;
let mayUseKeys = false;
function showRights() {
  $('command-form').hidden = !maySend;
  $('observer').hidden = maySend || mayUseKeys;
}
const LOCK = command('?lock', mailbox);
const [onBox, onServer] = await Promise.all([rights(mailbox), rights('', [LOCK])]);
maySend = onBox.send;
const mayLock = onServer.commands[LOCK];
$('take-lock').hidden = !mayLock;
$('release-lock').hidden = !mayLock;
showRights();
await Promise.all([refreshStatus(), calls.refresh()]);
document.body.dataset.ready = 'true';
