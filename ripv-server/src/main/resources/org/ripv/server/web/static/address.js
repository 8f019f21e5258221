// The one MailBox or service a page is about comes from its URL (?m=, ?s=), and a URL is anyone's link: it is
// taken only when it is one name by the address grammar of org.ripv.naming (MailboxAddress, ServiceName; the
// server's AddressGrammarTest keeps these three lines equal to it), and commands are built from words, never
// by pasting text, so '?m=add MAILBOX evil.wf' cannot become '?queue add MAILBOX evil.wf'.
export const SERVICE = '[A-Za-z][A-Za-z0-9_]{0,63}';
export const HOST = '[A-Za-z0-9._:%\\-]{1,253}';
export const HANDLE = '[A-Za-z0-9][A-Za-z0-9._\\-]{0,127}';

const MAILBOX = new RegExp(`^<${SERVICE}>::<${HOST}>${HANDLE}$`);
// A vehicle's own name (glider1): one word the server resolves to its MailBox, as the CLI's commands take it.
const VEHICLE = new RegExp(`^${HANDLE}$`);
const SERVICE_NAME = new RegExp(`^(?:${SERVICE}|<${SERVICE}>::<${HOST}>)$`);
// White space, C0/C1 controls, DEL, line and paragraph separators, bidi controls: nothing a word of a command may hold.
const NOT_A_WORD = /[\s\u0000-\u001f\u007f-\u009f\u2028\u2029\u202a-\u202e\u2066-\u2069]/u;

/** True when {@code text} is a MailBox's full address, <Service>::<host>HANDLE. */
export function isMailbox(text) {
  return typeof text === 'string' && MAILBOX.test(text);
}

/** True when {@code text} is a service's short name (ClockService) or full name (<ClockService>::<host>). */
export function isServiceName(text) {
  return typeof text === 'string' && SERVICE_NAME.test(text);
}

/** Thrown for a URL parameter or a command word the grammar has no place for; its message is for the page. */
export class NotAName extends Error {}

/**
 * The page's ?m= as a MailBox: { mailbox, handle }. Absent: empty. Anything else than one address: NotAName, quoting
 * what the link held (as text: it is shown with textContent only).
 */
export function mailboxFromUrl(search = location.search) {
  const m = new URLSearchParams(search).get('m');
  if (m === null || m === '') return { mailbox: '', handle: '' };
  if (VEHICLE.test(m)) return { mailbox: m, handle: m };
  if (!isMailbox(m)) {
    throw new NotAName(`'${m.length > 120 ? `${m.substring(0, 120)}…` : m}' is not a valid MailBox name (expected one address`
      + ' like <SerialPortServer>::<host>glider1, or a vehicle\'s name like glider1, no spaces); nothing was sent.'
      + ' Open the vehicle from the fleet page.');
  }
  return { mailbox: m, handle: m.substring(m.lastIndexOf('>') + 1) };
}

/** The page's ?s= as a service name, or null when absent; NotAName when it is anything else. */
export function serviceFromUrl(search = location.search) {
  const s = new URLSearchParams(search).get('s');
  if (s === null || s === '') return null;
  if (!isServiceName(s)) throw new NotAName(`'${s.length > 120 ? `${s.substring(0, 120)}…` : s}' is not a valid service name; nothing was sent.`);
  return s;
}

/** One command line from its words: each must be non-empty and hold no white space or control; NotAName otherwise. */
export function command(...words) {
  for (const w of words) {
    if (typeof w !== 'string' || w === '' || NOT_A_WORD.test(w)) {
      throw new NotAName(`'${String(w)}' cannot be one word of a command (empty, or it holds white space or a control character); nothing was sent.`);
    }
  }
  return words.join(' ');
}

/** Shows why the page stops (as an alert, text only) and stops the page's module by throwing. */
export function refuse(error, where = document.getElementById('name') || document.querySelector('main') || document.body) {
  const p = document.createElement('p');
  p.id = 'not-valid';
  p.className = 'error';
  p.setAttribute('role', 'alert');
  p.textContent = error.message;
  if (where === document.body) where.append(p); else where.after(p);
  document.body.dataset.ready = 'refused';
  throw error;
}
