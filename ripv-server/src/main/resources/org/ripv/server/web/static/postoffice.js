// The page's one WebSocket to the Post Office: requests out, replies and console pushes in.
// Every request carries the session's CSRF token; the server decides everything.
export async function session() {
  const r = await fetch('/api/session', { credentials: 'same-origin' });
  if (r.status === 401) { location.href = '/'; throw new Error('not logged in'); }
  return r.json();
}

export class PostOffice {
  constructor(csrf) {
    this.csrf = csrf;
    this.nextId = 1;
    this.waiting = new Map();
    this.onPush = () => {};
    this.onClose = () => {};
    const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
    this.socket = new WebSocket(`${scheme}//${location.host}/ws`);
    this.ready = new Promise((resolve, reject) => {
      this.socket.addEventListener('open', resolve, { once: true });
      this.socket.addEventListener('error', reject, { once: true });
    });
    this.socket.addEventListener('message', (e) => this.received(JSON.parse(e.data)));
    this.socket.addEventListener('close', (e) => this.onClose(e.reason || 'the connection closed'));
  }

  received(m) {
    if (m.type === 'push') { this.onPush(m); return; }
    const w = this.waiting.get(m.id);
    if (!w) { this.onPush(m); return; }
    // A query's rows come in pages (PROGRESS with a TableResult); the final reply gets them all, in order.
    if (m.status === 'PROGRESS' && m.result?.kind === 'TableResult') { (w.pages ??= []).push(m.result.rows); return; }
    if (m.status === 'PROGRESS') { w.progress(m); return; }
    this.waiting.delete(m.id);
    if (w.pages && m.result?.kind === 'TableResult') m.result.rows = [...w.pages, m.result.rows].flat();
    w.done(m);
  }

  /**
   * Sends a request. Returns at once a promise of its final reply (progress replies go to onProgress) that carries the
   * request's id as `.id`, so the caller can cancel what it started (?cancel ID) before the reply comes; extra: an
   * upload chunk (transfer.js).
   */
  send(mailbox, body, priority = 'normal', onProgress = () => {}, extra = {}) {
    const id = this.nextId++;
    const reply = new Promise((done) => this.waiting.set(id, { done, progress: onProgress }));
    this.ready.then(() => this.socket.send(JSON.stringify({ ...extra, id, mailbox, body, priority, csrf: this.csrf })),
      () => this.received({ id, status: 'ERROR', error: 'NOT_AVAILABLE', text: 'the connection to the server could not be opened' }));
    return Object.assign(reply, { id });
  }

  /** Cancels a request this page sent (its id from send's `.id`); resolves with the server's answer. */
  cancel(id) {
    return this.send('', `?cancel ${id}`);
  }
}

/** A header bar with the user's name and a Log out button (a form with the CSRF token). */
export function bar(s) {
  const header = document.createElement('header');
  header.className = 'bar';
  const nav = document.createElement('nav');
  const fleet = document.createElement('a');
  fleet.href = '/fleet.html';
  fleet.textContent = 'Fleet';
  const notify = document.createElement('a');
  notify.href = '/notify.html';
  notify.textContent = 'Notifications';
  nav.append(fleet, notify);
  for (const [href, text] of [['/changes.html', 'Changes'], ['/data.html', 'Data'], ['/service.html', 'Services']]) {
    const a = document.createElement('a');
    a.href = href;
    a.textContent = text;
    nav.append(a);
  }
  const who = document.createElement('span');
  who.id = 'who';
  who.textContent = `${s.user} (${s.roles.join(', ')})`;
  const form = document.createElement('form');
  form.method = 'post';
  form.action = '/logout';
  const token = document.createElement('input');
  token.type = 'hidden'; token.name = 'csrf'; token.value = s.csrf;
  const out = document.createElement('button');
  out.type = 'submit'; out.className = 'secondary'; out.textContent = 'Log out';
  form.append(token, out);
  header.append(nav, who, form);
  document.body.prepend(header);
}

export { ago } from './time.js';
