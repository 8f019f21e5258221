// The user's own notification subscriptions, with ?notify list / add / remove: the server applies the webhook right,
// the address rules and the limits, and keeps each subscription's last result.
import { session, PostOffice, bar } from './postoffice.js';
import { el, button, say } from './ui.js';

const s = await session();
bar(s);
const po = new PostOffice(s.csrf);
const $ = (id) => document.getElementById(id);

async function list() {
  const r = await po.send('', '?notify list');
  if (r.status === 'ERROR') { say($('list-status'), r); return; }
  $('list-status').textContent = r.text.split('\n')[0];
  $('subscriptions').replaceChildren(...(r.result?.subscriptions || []).map((n) => {
    const li = el('li', '', { 'data-id': n.id });
    const bad = n.lastResult.startsWith('failed') || n.lastResult.startsWith('not ');
    li.append(el('div', `${n.channel} ${n.target}`, { class: 'target' }), el('div', `events ${n.events} · MailBoxes ${n.mailboxes}`, { class: 'status' }),
      el('div', `last: ${n.lastResult}`, { class: bad ? 'last bad' : 'last' }));
    li.append(button('Remove', async () => {
      say($('list-status'), await po.send('', `?notify remove ${n.id}`));
      list();
    }));
    return li;
  }));
}

$('channel').addEventListener('change', () => {
  $('target').placeholder = $('channel').value === 'email' ? 'pilot@example.org' : 'https://hooks.example.org/ripv';
});
$('add-form').addEventListener('submit', async (e) => {
  e.preventDefault();
  const words = [$('channel').value, $('target').value.trim(), $('events').value.trim() || 'all', $('glob').value.trim() || '*'];
  if (words.slice(1).some((w) => /\s/.test(w)) || !words[1]) {
    say($('add-status'), { status: 'ERROR', text: 'the address, events and glob are one word each (no spaces)' });
    return;
  }
  const r = await po.send('', `?notify add ${words.join(' ')}`);
  say($('add-status'), r);
  if (r.status !== 'ERROR') list();
});
$('refresh').addEventListener('click', list);
await list();
document.body.dataset.ready = 'true';
