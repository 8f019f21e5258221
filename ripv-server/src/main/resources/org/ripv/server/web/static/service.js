// Any registered service, known to the console or not: its MailBoxes, a command line, the replies.
// Nothing here names a service; a new service needs no web code (thesis 7.2.1). Replies are shown
// as text (and tables as tables), whatever the service sends.
import { session, PostOffice, bar } from './postoffice.js';
import { tableElement } from './table.js';
import { vehicleName } from './names.js';
import { serviceFromUrl, refuse } from './address.js';

const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
const $ = (id) => document.getElementById(id);
po.onClose = (why) => { $('state').textContent = `Disconnected: ${why}. Reload the page to reconnect.`; };
let wanted;
try {
  wanted = serviceFromUrl(); // one service name, or the page says the link's name is not valid and stops
} catch (e) {
  refuse(e, $('state'));
}

const services = (await po.send('', '?services')).result?.services || [];
const statuses = (await po.send('', '?mailboxes')).result?.mailboxes || [];
const option = (value, text) => { const o = document.createElement('option'); o.value = value; o.textContent = text; return o; };
$('service').replaceChildren(...services.map((d) => option(d.name, d.name)));
// A service's name is its full prefix (<ClockService>::<host>); ?s= may give that or the short name.
const picked = services.find((d) => d.name === wanted || d.name.startsWith(`<${wanted}>`));
if (picked) $('service').value = picked.name;
$('state').textContent = services.length ? `${services.length} service(s) registered.` : 'No service is registered.';

function show() {
  const name = $('service').value;
  const d = services.find((x) => x.name === name);
  $('name').textContent = name || 'Services';
  document.title = `RIPV ${name}`;
  $('about').textContent = d ? `${d.description} (SID ${d.sid})` : '';
  const mine = statuses.filter((m) => m.address.startsWith(name));
  $('mailboxes').replaceChildren(...mine.map((m) => {
    const tr = document.createElement('tr');
    tr.dataset.address = m.address;
    const cells = [vehicleName(m.address), m.available ? (m.busy ? 'busy' : 'ready') : 'not available', m.detail, m.lockedBy || ''];
    tr.append(...cells.map((t) => { const td = document.createElement('td'); td.textContent = t; return td; }));
    tr.firstChild.title = m.address;
    return tr;
  }));
  $('mailbox').replaceChildren(...mine.map((m) => option(m.address, vehicleName(m.address))));
  history.replaceState(null, '', `?s=${encodeURIComponent(name.replace(/^<([^>]*)>.*$/, '$1'))}`);
}
$('service').addEventListener('change', show);
show();

function entry(text, cls) {
  const div = document.createElement('div');
  div.className = cls;
  div.textContent = text;
  return div;
}

// A result the page has no view for is shown as its fields, as text: every service's replies are readable.
function resultNodes(r) {
  if (!r) return [];
  if (r.kind === 'TableResult') { const w = document.createElement('div'); w.className = 'scroll'; w.append(tableElement(r)); return [w]; }
  const { kind, ...fields } = r;
  return [entry(`${kind} ${JSON.stringify(fields, null, 2)}`, 'result')];
}

$('command-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  const body = $('command').value.trim();
  const mailbox = $('mailbox').value;
  if (!body || !mailbox) return;
  $('command').value = '';
  const box = $('replies');
  box.append(entry(`${vehicleName(mailbox)}> ${body}`, 'COMMAND'));
  const r = await po.send(mailbox, body, 'normal', (p) => box.append(entry(p.text, 'progress')));
  box.append(entry(r.status === 'ERROR' ? `Error: ${r.text} [${r.error}]` : r.text, r.status === 'ERROR' ? 'error' : 'reply'), ...resultNodes(r.result));
  box.scrollTop = box.scrollHeight;
});
