// The vehicle page's links to its files and its queue, for the MailBox in this page's ?m=.
const m = new URLSearchParams(location.search).get('m') || '';
for (const id of ['files-link', 'queue-link']) {
  const a = document.getElementById(id);
  a.href = `${a.pathname}?m=${encodeURIComponent(m)}`;
}
