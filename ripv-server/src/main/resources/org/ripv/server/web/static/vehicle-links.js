// The vehicle page's links to its files and its queue, for the MailBox in this page's ?m=.
import { isMailbox } from './address.js';

const given = new URLSearchParams(location.search).get('m') || '';
const m = isMailbox(given) ? given : ''; // vehicle.js says why a name is not valid
for (const id of ['files-link', 'queue-link']) {
  const a = document.getElementById(id);
  a.href = `${a.pathname}?m=${encodeURIComponent(m)}`;
}
