// A MailBox's workflow queue and receipts, with the CLI's own commands (?queue, ?receipts): the server parses, checks
// rights and runs; this page shows what it says. A refused workflow's FILE:LINE: reason is shown at that line.
import { session, PostOffice, bar } from './postoffice.js';
import { upload, storedName } from './transfer.js';
import { el, button, say, mailboxParam, vehicleNav } from './ui.js';
import { rights } from './rights.js';
import { command, NotAName } from './address.js';

const { mailbox, handle } = mailboxParam();
const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
document.getElementById('name').textContent = `Queue and receipts of ${handle}`;
document.title = `RIPV queue ${handle}`;
document.querySelector('main').prepend(vehicleNav(mailbox, 'queue.html'));
const $ = (id) => document.getElementById(id);
// What the permit file lets this user do with the queue (the server decides each command again).
const ADD = command('?queue', 'add', mailbox, 'x.wf'), REMOVE = command('?queue', 'remove', mailbox, '1'), CLEAR = command('?queue', 'clear', mailbox);
const may = (await rights('', [ADD, REMOVE, CLEAR])).commands;

// "   3  alice      once         fetch.wf  2 step(s), queued" — the listing's rows start with the workflow's id.
const ROW = /^\s*(\d+)\s+(\S+)\s+(\S+)\s+(.*)$/;

async function listQueue() {
  const r = await po.send('', command('?queue', mailbox));
  if (r.status === 'ERROR') { say($('queue-status'), r); return; }
  const lines = r.text.split('\n');
  $('queue-status').textContent = lines[0];
  $('queue').replaceChildren(...lines.slice(1).map((l) => ROW.exec(l)).filter(Boolean).map((m) => {
    const li = el('li', '', { 'data-id': m[1] });
    li.append(el('span', `#${m[1]} ${m[4]} (${m[2]}, ${m[3]})`));
    if (may[REMOVE]) {
      li.append(button('Remove', async () => {
        const x = await po.send('', command('?queue', 'remove', mailbox, m[1]));
        say($('queue-reply'), { ...x, text: x.text.split('\n')[0] });
        if (x.status !== 'ERROR') listQueue();
      }));
    }
    return li;
  }));
}

async function listStore() {
  const r = await po.send('', '?ulfiles');
  // Workflows only (NAME.wf, as docs/workflows.md names them): the store also holds missions and data files.
  const names = (r.result?.files || []).map((f) => f.name).filter((n) => /\.wf$/i.test(n)).sort();
  $('wf-stored').replaceChildren(...names.map((n) => el('option', n, { value: n })));
}

/** The workflow's lines, numbered, with the parser's reason under the line it names. */
function showLines(text, reply, file) {
  const box = $('wf-lines');
  const m = reply.status === 'ERROR' ? /^(.+?):(\d+): ([\s\S]*)$/.exec(reply.text) : null;
  if (!m || (file && m[1] !== file)) { box.hidden = true; return; }
  const at = Number(m[2]);
  box.replaceChildren(...text.replace(/\n$/, '').split('\n').map((line, i) => {
    const li = el('li', line || ' ');
    if (i + 1 === at) {
      li.className = 'bad';
      li.id = 'error-line';
      li.append(el('div', `${m[1]}:${m[2]}: ${m[3]}`, { class: 'why', role: 'alert' }));
    }
    return li;
  }));
  box.hidden = false;
  if (at === 0) box.prepend(el('li', `${m[1]}:0: ${m[3]}`, { class: 'bad why', role: 'alert' }));
  document.getElementById('error-line')?.scrollIntoView({ block: 'nearest' });
}

async function queueFile(name, text) {
  let line;
  try {
    line = command('?queue', 'add', mailbox, name);
  } catch (e) {
    if (!(e instanceof NotAName)) throw e;
    say($('add-status'), { status: 'ERROR', text: e.message });
    return { status: 'ERROR', text: e.message };
  }
  const r = await po.send('', line);
  say($('add-status'), r.status === 'ERROR' ? r : { ...r, text: r.text.split('\n')[0] }); // the listing is shown above
  showLines(text ?? '', r, name);
  if (r.status !== 'ERROR') listQueue();
  return r;
}

// A file from the browser or the text box goes into the upload store first (as 'put' does in the CLI), under a free
// name if that one is taken, then ?queue add names it: the server parses it and says where it is wrong.
async function uploadAndQueue(name, text) {
  const up = await upload(po, name, new TextEncoder().encode(text), 'keep');
  if (up.status === 'ERROR') { say($('add-status'), up); return; }
  await queueFile(storedName(up, name), text);
  listStore();
}

$('file-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  const f = $('wf-file').files[0];
  if (!f) { say($('add-status'), { status: 'ERROR', text: 'choose a workflow file first' }); return; }
  await uploadAndQueue(f.name, await f.text());
});
$('stored-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  if ($('wf-stored').value) await queueFile($('wf-stored').value, null);
});
$('typed-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  await uploadAndQueue($('wf-name').value.trim(), $('wf-text').value);
});
$('refresh-queue').addEventListener('click', listQueue);
$('clear-queue').addEventListener('click', async () => {
  if (!confirm(`Remove every workflow from the queue of ${handle}?`)) return;
  say($('queue-reply'), await po.send('', command('?queue', 'clear', mailbox)));
  listQueue();
});

async function listReceipts() {
  const r = await po.send('', command('?receipts', mailbox, '--last', '50'));
  if (r.status === 'ERROR') { say($('receipts-status'), r); return; }
  const [head, ...rest] = r.text.split('\n\n');
  // The server lists them oldest first, each beginning "receipt: workflow ID 'FILE' of OWNER …"; the page shows them
  // newest first, opened on a click, and says so.
  $('receipts-status').textContent = /oldest first\s*$/.test(head) ? head.replace(/oldest first\s*$/, 'newest first') : head;
  const receipts = rest.join('\n\n').split(/\n(?=receipt: )/).filter((t) => t.startsWith('receipt: ')).reverse();
  $('receipts').replaceChildren(...receipts.map((t) => {
    const d = el('details', '', { class: 'receipt' });
    const result = /^result: (\S+)/m.exec(t);
    d.append(el('summary', `${t.split('\n')[0].substring(9)}${result ? ` — ${result[1]}` : ''}`), el('pre', t));
    return d;
  }));
}
$('refresh-receipts').addEventListener('click', listReceipts);
$('add').hidden = !may[ADD];
$('clear-queue').hidden = !may[CLEAR];
// A workflow's events arrive on the MailBox's console stream: the queue and receipts follow them.
po.onPush = (m) => {
  if (m.result?.kind === 'ConsoleBatch' && m.result.mailbox === mailbox && m.result.entries.some((e) => e.event?.startsWith('WORKFLOW'))) {
    listQueue();
    listReceipts();
  }
};
await Promise.all([listQueue(), listStore(), listReceipts(), po.send('', command('?watch', mailbox))]);
document.body.dataset.ready = 'true';
