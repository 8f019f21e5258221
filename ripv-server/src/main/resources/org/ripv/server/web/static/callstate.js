// A vehicle's call state as the vehicle page shows it — on call, dived, link lost — and when it dives. It is fed what
// the server says: the MailBox's session state (?status), the console's events (SURFACED, DIVED, LINK_LOST) and, when
// the server sends it, `diveAt` (epoch ms: when the dialog's "Hit Control-C within N seconds" countdown ends). Without
// that field the countdown line itself, as the vehicle printed it, gives the time.
export const WORDS = { ON_CALL: 'on call', DIVED: 'dived', LOST: 'link lost', UNKNOWN: 'unknown' };
const COUNTDOWN = /Hit Control-C within (\d{1,5}) seconds/;
const BY_EVENT = { SURFACED: 'ON_CALL', DIVED: 'DIVED', LINK_LOST: 'LOST' };

export class CallState {
  constructor() {
    this.state = 'UNKNOWN';
    this.diveAt = null;
    this.serverCounts = false; // the server sent diveAt once: its word wins over the line from then on
  }

  /** A SessionState as ?status and ?mailboxes carry it (and any push of the state). */
  takeSession(s) {
    if (!s) return;
    if (s.state) this.state = s.state;
    if ('diveAt' in s) { this.serverCounts = true; this.diveAt = s.diveAt || null; }
    if (this.state !== 'ON_CALL') this.diveAt = null;
  }

  /** One console entry of this MailBox, in the order the console shows them. */
  takeEntry(e) {
    if (e.kind === 'EVENT' && BY_EVENT[e.event]) {
      this.state = BY_EVENT[e.event];
      this.diveAt = null;
    }
    if (e.diveAt !== undefined) { this.serverCounts = true; this.diveAt = e.diveAt || null; }
    if (e.kind === 'COMMAND' && /^\?key ctrl-[cr]\b/i.test(e.text)) this.diveAt = null; // the pilot answered the countdown
    if (!this.serverCounts && e.kind === 'LINE' && this.state !== 'DIVED' && this.state !== 'LOST') {
      const m = COUNTDOWN.exec(e.text);
      if (m) this.diveAt = e.time + Number(m[1]) * 1000;
    }
  }

  /** Whole seconds until the dive, or null when no countdown runs (none, or its time has passed). */
  secondsLeft(now = Date.now()) {
    if (this.diveAt == null || this.state !== 'ON_CALL' && this.state !== 'UNKNOWN') return null;
    const s = Math.ceil((this.diveAt - now) / 1000);
    return s >= 0 ? s : null;
  }

  words() {
    return WORDS[this.state] || this.state.toLowerCase().replace('_', ' ');
  }
}

/** The control keys a MailBox's link lets ?key press, from its status detail ("...; keys: ctrl-c, ctrl-r"); [] when it names none. */
export function linkKeys(detail) {
  const m = /keys: ((?:ctrl-[a-z](?:, )?)+)/i.exec(detail || '');
  return m ? m[1].split(', ').map((k) => k.trim().toLowerCase()).filter(Boolean) : [];
}
