// A vehicle's goto list edited as a table: load a file (?plan check), add, move (type) and remove waypoints, edit
// b_args, save the new file into the upload store and check it (the server's FILE:LINE: reasons under the form), send
// it on the next call (?plan send), queue a put (?plan set), and follow every change (?changes) as its events arrive.
import { session, PostOffice, bar } from './postoffice.js';
import { upload, storedName } from './transfer.js';
import { el, button, say, mailboxParam, vehicleNav } from './ui.js';
import { rights } from './rights.js';
import { command } from './address.js';

const { mailbox, handle } = mailboxParam();
const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
document.getElementById('name').textContent = `Plan of ${handle}`;
document.title = `RIPV plan ${handle}`;
document.querySelector('main').prepend(vehicleNav(mailbox, 'plan.html'));
const $ = (id) => document.getElementById(id);

const DEFAULT_BARGS = [
  ['num_legs_to_run', 'nodim', '-1', 'loop'], ['start_when', 'enum', '0', 'BAW_IMMEDIATELY'],
  ['list_stop_when', 'enum', '7', 'BAW_WHEN_WPT_DIST'], ['initial_wpt', 'enum', '-2', '0 to N-1, -1 after the last achieved, -2 the closest'],
  ['num_waypoints', 'nodim', '0', ''],
];
let saved = null; // the name the last saved file is stored under

function input(value, label, cls) {
  return el('input', '', { value, 'aria-label': label, class: cls, autocomplete: 'off', spellcheck: 'false' });
}

function addWaypoint(lat = '', lon = '', comment = '') {
  const tr = el('tr');
  const n = el('td');
  tr.append(n, el('td'), el('td'), el('td'), el('td'));
  tr.children[1].append(input(lat, 'latitude', 'lat'));
  tr.children[2].append(input(lon, 'longitude', 'lon'));
  tr.children[3].append(input(comment, 'comment', 'comment'));
  tr.children[4].append(button('Remove', () => { tr.remove(); renumber(); }));
  $('wpts').tBodies[0].append(tr);
  renumber();
}

function renumber() {
  const rows = [...$('wpts').tBodies[0].rows];
  rows.forEach((tr, i) => { tr.cells[0].textContent = String(i); });
  const count = document.querySelector("#bargs tr[data-name='num_waypoints'] .value");
  if (count) count.value = String(rows.length); // counted, never typed: the glider reads exactly this many
}

function showBargs(bargs) {
  $('bargs').tBodies[0].replaceChildren(...bargs.map(([name, units, value, comment]) => {
    const tr = el('tr', '', { 'data-name': name, 'data-units': units });
    tr.append(el('td', `${name}(${units})`), el('td'), el('td'));
    const v = input(value, `${name} value`, 'value');
    if (name === 'num_waypoints') v.readOnly = true;
    tr.children[1].append(v);
    tr.children[2].append(input(comment, `${name} comment`, 'comment'));
    return tr;
  }));
}

/** Decimal degrees as Slocum's DDMM.mmmm, the sign in front. */
function ddmm(deg) {
  const a = Math.abs(deg);
  let d = Math.floor(a);
  let m = (a - d) * 60;
  if (m >= 59.99995) { d += 1; m = 0; }
  return `${deg < 0 ? '-' : ''}${d}${m.toFixed(4).padStart(7, '0')}`;
}

/** The file the table says, as the glider reads it (num_waypoints counted here). */
function fileText(name) {
  const rows = [...$('wpts').tBodies[0].rows];
  const lines = ['behavior_name=goto_list', `# ${name} written in the RIPV web console by ${s.user} at ${new Date().toISOString()}`,
    '', '<start:b_arg>'];
  let counted = false;
  for (const tr of $('bargs').tBodies[0].rows) {
    let value = tr.querySelector('.value').value.trim();
    if (tr.dataset.name === 'num_waypoints') { value = String(rows.length); counted = true; }
    const comment = tr.querySelector('.comment').value.trim();
    lines.push(`\tb_arg: ${tr.dataset.name}(${tr.dataset.units}) ${value}${comment ? ` # ${comment}` : ''}`);
  }
  if (!counted) lines.push(`\tb_arg: num_waypoints(nodim) ${rows.length}`);
  lines.push('<end:b_arg>', '<start:waypoints>', '# LON LAT');
  for (const tr of rows) {
    const lat = tr.querySelector('.lat').value.trim();
    const lon = tr.querySelector('.lon').value.trim();
    const comment = tr.querySelector('.comment').value.trim();
    // a value that is not a number goes as typed: the server's check says where it is wrong
    const f = (v) => (v !== '' && Number.isFinite(Number(v)) ? ddmm(Number(v)) : (v || '?'));
    lines.push(`${f(lon)}\t${f(lat)}${comment ? ` # ${comment}` : ''}`);
  }
  lines.push('<end:waypoints>', '');
  return lines.join('\n');
}

// "  initial_wpt(enum)       -2  # the closest": the b_args as ?plan check prints them.
const BARG = /^ {2}(\w+)\(([^()]*)\)\s+(\S+)(?:\s+# (.*))?$/;

async function load(e) {
  e?.preventDefault();
  const name = $('plan-file').value.trim();
  const r = await po.send('', `?plan ${mailbox} check ${name}`);
  say($('load-status'), r.status === 'ERROR' ? r : { ...r, text: r.text.split('\n').slice(0, 2).join(' — ') });
  if (r.status === 'ERROR') return;
  $('wpts').tBodies[0].replaceChildren();
  for (const [, lat, lon, comment] of r.result?.rows || []) addWaypoint(lat, lon, comment ?? '');
  const bargs = r.text.split('\n').slice(r.text.split('\n').indexOf('b_args:') + 1).map((l) => BARG.exec(l)).filter(Boolean)
    .map((m) => [m[1], m[2], m[3], m[4] ?? '']);
  showBargs(bargs);
  renumber();
}

function showProblems(reply) {
  const lines = reply.status === 'ERROR' ? reply.text.split('\n').filter((l) => /^.+?:\d+: /.test(l)) : [];
  $('problems').replaceChildren(...lines.map((l) => el('li', l, { role: 'alert' })));
  $('problems').hidden = lines.length === 0;
}

async function save(e) {
  e.preventDefault();
  const name = $('save-name').value.trim();
  const up = await upload(po, name, new TextEncoder().encode(fileText(name)), 'keep');
  if (up.status === 'ERROR') { say($('save-status'), up); return; }
  saved = storedName(up, name);
  const r = await po.send('', `?plan ${mailbox} check ${saved}`);
  say($('save-status'), r.status === 'ERROR' ? { ...r, text: `${saved} was saved but does not pass the check` }
    : { ...r, text: `saved and checked: ${r.text.split('\n')[1]}` });
  showProblems(r);
  $('send').disabled = r.status === 'ERROR';
}

async function send(e) {
  e.preventDefault();
  if (!saved) { say($('send-status'), { status: 'ERROR', text: 'save the file first' }); return; }
  const r = await po.send('', `?plan ${mailbox} send ${saved} as ${$('send-as').value.trim()}`);
  say($('send-status'), r.status === 'ERROR' ? r : { ...r, text: r.text.split('\n')[0] });
  showProblems(r);
  listChanges();
}

async function set(e) {
  e.preventDefault();
  const r = await po.send('', `?plan ${mailbox} set ${$('set-name').value.trim()} ${$('set-value').value.trim()}`);
  say($('set-status'), r);
  listChanges();
}

async function forecast() {
  const name = saved || $('plan-file').value.trim();
  const r = await po.send('', `?plan ${mailbox} forecast ${name}`);
  $('forecast-text').textContent = r.status === 'ERROR' ? `Error: ${r.text}` : r.text;
  $('forecast-text').hidden = false;
}

// "   1  in effect      goto_l10.ma (from goto_l11.ma)  [since …, by alice]" then the reason, indented.
const CHANGE = /^\s*(\d+) {2}(.{14}) (.*)$/;

async function listChanges() {
  const r = await po.send('', `?changes ${mailbox}`);
  if (r.status === 'ERROR') { say($('changes-status'), r); return; }
  const lines = r.text.split('\n');
  $('changes-status').textContent = lines[0];
  const items = [];
  for (let i = 1; i < lines.length; i += 2) {
    const m = CHANGE.exec(lines[i]);
    if (!m) continue;
    const li = el('li', '', { 'data-id': m[1], 'data-state': m[2].trim() });
    li.append(el('span', `#${m[1]} `), el('span', m[2].trim(), { class: 'state' }), el('span', ` ${m[3]}`),
      el('div', (lines[i + 1] || '').trim(), { class: 'why' }));
    items.push(li);
  }
  $('changes').replaceChildren(...items.reverse());
}

$('load-form').addEventListener('submit', load);
$('add-wpt').addEventListener('click', () => addWaypoint());
$('save-form').addEventListener('submit', save);
$('send-form').addEventListener('submit', send);
$('set-form').addEventListener('submit', set);
$('forecast').addEventListener('click', forecast);
$('refresh-changes').addEventListener('click', listChanges);
// What the permit file lets this user change (the server decides each command again when it is sent).
const SEND = command('?plan', mailbox, 'send', 'goto_l10.ma'), SET = command('?plan', mailbox, 'set', 'x', '0');
const may = (await rights('', [SEND, SET])).commands;
if (!may[SEND]) $('save-card').hidden = true;
if (!may[SET]) $('set-card').hidden = true;
// A change's state moves with PLAN_CHANGE events on the MailBox's console stream.
po.onPush = (m) => {
  if (m.result?.kind === 'ConsoleBatch' && m.result.mailbox === mailbox && m.result.entries.some((x) => x.event === 'PLAN_CHANGE')) {
    listChanges();
  }
};
showBargs(DEFAULT_BARGS);
await Promise.all([listChanges(), po.send('', `?watch ${mailbox}`)]);
document.body.dataset.ready = 'true';
