import { mailboxFromUrl, refuse, NotAName } from './address.js';

// Small DOM helpers for the files, queue and notifications pages. Text from vehicles, files and the server is only
// ever set as textContent: whatever it holds stays text.

/** An element with text (never parsed as HTML) and attributes. */
export function el(tag, text = '', attrs = {}) {
  const e = document.createElement(tag);
  if (text) e.textContent = text;
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
}

export function button(text, onClick, cls = 'secondary') {
  const b = el('button', text, { type: 'button', class: cls });
  b.addEventListener('click', onClick);
  return b;
}

/** Shows a reply's text in a status line: an ERROR in the error colour, as an alert. */
export function say(line, reply) {
  line.textContent = reply.status === 'ERROR' ? `Error: ${reply.text}` : reply.text;
  line.setAttribute('role', reply.status === 'ERROR' ? 'alert' : 'status');
}

/** The MailBox the page is about (?m=…), and the vehicle's name in it; a link holding anything else stops the page, saying so. */
export function mailboxParam() {
  try {
    const m = mailboxFromUrl();
    if (!m.mailbox) throw new NotAName('This page is about one MailBox, and the link names none: open it from the fleet page.');
    return m;
  } catch (e) {
    return refuse(e);
  }
}

/** Links between a vehicle's pages, kept in the ?m= of the page. */
export function vehicleNav(mailbox, here) {
  const nav = el('nav', '', { class: 'row tabs', 'aria-label': 'this vehicle' });
  for (const [page, text] of [['vehicle.html', 'Console'], ['files.html', 'Files'], ['queue.html', 'Queue and receipts'], ['plan.html', 'Plan']]) {
    const a = el('a', text, { href: `/${page}?m=${encodeURIComponent(mailbox)}` });
    if (page === here) a.setAttribute('aria-current', 'page');
    nav.append(a);
  }
  return nav;
}
